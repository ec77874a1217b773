#pragma once
// Dc element: distributed-clock operation modes.

#include "esi/model/common.hpp"

namespace esi {

// CycleTimeSync0/1 and ShiftTimeSync0/1: a time in ns with an optional Factor.
struct DcTime {
    std::int64_t value = 0;
    std::optional<std::int32_t> factor;
    std::optional<bool> input;  // shift times only
    std::optional<std::int32_t> output_delay_time;
    std::optional<std::int32_t> input_delay_time;
    SourcePos pos;
};

struct DcOpMode {
    std::string name;
    std::optional<std::string> desc;
    std::uint32_t assign_activate = 0;
    bool has_assign_activate = false;
    SourcePos assign_activate_pos;
    std::optional<DcTime> cycle_time_sync0;
    std::optional<DcTime> shift_time_sync0;
    std::optional<DcTime> cycle_time_sync1;
    std::optional<DcTime> shift_time_sync1;
    SourcePos pos;
    Extras extras;  // Dc/OpMode/Sm, VendorSpecific
};

struct Dc {
    std::vector<DcOpMode> op_modes;
    std::optional<bool> unknown_frmw;
    std::optional<bool> unknown_64bit;
    std::optional<bool> external_ref_clock;
    std::optional<bool> potential_reference_clock;
    std::optional<bool> time_loop_control_only;
    SourcePos pos;
    Extras extras;
};

}  // namespace esi
