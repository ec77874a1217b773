#pragma once
// Sm, Fmmu and Su elements of a device (ETG.2000 DeviceType).

#include "esi/model/common.hpp"

namespace esi {

// <Sm StartAddress="#x1000" ControlByte="#x26" DefaultSize="128" Enable="1">MBoxOut</Sm>
struct SyncManager {
    std::string type;  // text: MBoxOut, MBoxIn, Outputs, Inputs (or empty)
    std::optional<std::uint32_t> start_address;
    std::optional<std::uint32_t> control_byte;
    std::optional<std::uint32_t> default_size;
    std::optional<std::uint32_t> min_size;
    std::optional<std::uint32_t> max_size;
    std::optional<std::uint32_t> enable;
    std::optional<bool> one_byte_mode;  // deprecated (CTT 5-8)
    std::optional<bool> is_virtual;
    std::optional<bool> watchdog;
    std::optional<bool> op_only;
    std::optional<bool> fixed_assignment;
    SourcePos pos;
    Extras extras;
};

// <Fmmu Sm="2">Outputs</Fmmu>
struct Fmmu {
    std::string type;  // Outputs, Inputs, MBoxState, DynamicInputs, DynamicOutputs
    std::optional<std::uint32_t> sm;
    std::optional<std::uint32_t> su;
    std::optional<bool> op_only;  // deprecated (CTT 5-7)
    SourcePos pos;
    Extras extras;
};

// <Su SeparateSu="1">…</Su>: sync units
struct SyncUnit {
    std::string text;
    std::optional<bool> separate_su;
    std::optional<bool> separate_frame;
    std::optional<bool> depend_on_input_state;
    std::optional<bool> frame_repeat_support;
    SourcePos pos;
    Extras extras;
};

}  // namespace esi
