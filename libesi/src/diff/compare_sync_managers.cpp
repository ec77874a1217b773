// SyncManagers, FMMUs and sync units. The n-th Sm element is SyncManager n and the n-th Fmmu is
// FMMU n (ETG.2000 DeviceType), so they pair up by position, not by content.

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "diff/compare.hpp"

namespace esi::diff_detail {

namespace {

bool same_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

void compare_sm(Recorder& r, const std::string& p, const SyncManager& a, const SyncManager& b) {
    if (a.type != b.type) {
        if (same_ignoring_case(a.type, b.type))
            r.value(ChangeKind::spelling_changed, p, "SyncManager type", quote(a.type), quote(b.type), a.pos, b.pos);
        else if (a.type.empty())
            r.value(ChangeKind::sm_type_declared, p, "SyncManager type", quote(a.type), quote(b.type), a.pos, b.pos);
        else
            r.value(ChangeKind::sm_type_changed, p, "SyncManager type", quote(a.type), quote(b.type), a.pos, b.pos);
    }
    r.value(ChangeKind::sm_address_changed, attr(p, "StartAddress"), "StartAddress", hex(a.start_address), hex(b.start_address),
            a.pos, b.pos);
    r.value(ChangeKind::sm_control_byte_changed, attr(p, "ControlByte"), "ControlByte", hex(a.control_byte, 2),
            hex(b.control_byte, 2), a.pos, b.pos);
    r.value(ChangeKind::sm_size_changed, attr(p, "DefaultSize"), "DefaultSize", dec(a.default_size), dec(b.default_size), a.pos,
            b.pos);
    // MinSize/MaxSize bound what a configuration may set; absent means unbounded.
    const std::uint64_t old_min = a.min_size.value_or(0);
    const std::uint64_t new_min = b.min_size.value_or(0);
    const std::uint64_t old_max = a.max_size ? *a.max_size : UINT64_MAX;
    const std::uint64_t new_max = b.max_size ? *b.max_size : UINT64_MAX;
    const bool narrowed = new_min > old_min || new_max < old_max;
    const ChangeKind limits = narrowed ? ChangeKind::sm_size_limits_narrowed : ChangeKind::sm_size_limits_widened;
    r.value(limits, attr(p, "MinSize"), "MinSize", dec(a.min_size), dec(b.min_size), a.pos, b.pos);
    r.value(limits, attr(p, "MaxSize"), "MaxSize", dec(a.max_size), dec(b.max_size), a.pos, b.pos);
    r.value(ChangeKind::sm_enable_changed, attr(p, "Enable"), "Enable", dec(a.enable), dec(b.enable), a.pos, b.pos);
    r.value(ChangeKind::sm_flag_changed, attr(p, "OneByteMode"), "OneByteMode", flag(a.one_byte_mode), flag(b.one_byte_mode),
            a.pos, b.pos);
    r.value(ChangeKind::sm_flag_changed, attr(p, "Virtual"), "Virtual", flag(a.is_virtual), flag(b.is_virtual), a.pos, b.pos);
    r.value(ChangeKind::sm_flag_changed, attr(p, "Watchdog"), "Watchdog", flag(a.watchdog), flag(b.watchdog), a.pos, b.pos);
    r.value(ChangeKind::sm_flag_changed, attr(p, "OpOnly"), "OpOnly", flag(a.op_only), flag(b.op_only), a.pos, b.pos);
    r.value(ChangeKind::sm_flag_changed, attr(p, "FixedAssignment"), "FixedAssignment", flag(a.fixed_assignment),
            flag(b.fixed_assignment), a.pos, b.pos);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

std::string describe_sm(const SyncManager& sm) {
    return fmt::format("{} {} size {}", sm.type.empty() ? std::string("(no type)") : sm.type,
                       sm.start_address ? hex(*sm.start_address) : std::string("?"),
                       sm.default_size ? std::to_string(*sm.default_size) : std::string("?"));
}

std::string describe_fmmu(const Fmmu& f) { return f.sm ? fmt::format("{} (Sm {})", f.type, *f.sm) : f.type; }

}  // namespace

void compare_sync_managers(Recorder& r, const Device& a, const Device& b) {
    const std::size_t sms = std::max(a.sms.size(), b.sms.size());
    for (std::size_t i = 0; i < sms; ++i) {
        const std::string p = indexed("Sm", std::to_string(i));
        if (i >= a.sms.size())
            r.add(ChangeKind::sm_added, p, std::nullopt, describe_sm(b.sms[i]), a.pos, b.sms[i].pos,
                  fmt::format("SyncManager {} added", i));
        else if (i >= b.sms.size())
            r.add(ChangeKind::sm_removed, p, describe_sm(a.sms[i]), std::nullopt, a.sms[i].pos, b.pos,
                  fmt::format("SyncManager {} removed", i));
        else
            compare_sm(r, p, a.sms[i], b.sms[i]);
    }

    const std::size_t fmmus = std::max(a.fmmus.size(), b.fmmus.size());
    for (std::size_t i = 0; i < fmmus; ++i) {
        const std::string p = indexed("Fmmu", std::to_string(i));
        if (i >= a.fmmus.size()) {
            r.add(ChangeKind::fmmu_added, p, std::nullopt, describe_fmmu(b.fmmus[i]), a.pos, b.fmmus[i].pos,
                  fmt::format("FMMU {} added", i));
            continue;
        }
        if (i >= b.fmmus.size()) {
            r.add(ChangeKind::fmmu_removed, p, describe_fmmu(a.fmmus[i]), std::nullopt, a.fmmus[i].pos, b.pos,
                  fmt::format("FMMU {} removed", i));
            continue;
        }
        const Fmmu& x = a.fmmus[i];
        const Fmmu& y = b.fmmus[i];
        r.value(x.type != y.type && same_ignoring_case(x.type, y.type) ? ChangeKind::spelling_changed : ChangeKind::fmmu_changed,
                p, "FMMU type", quote(x.type), quote(y.type), x.pos, y.pos);
        r.value(ChangeKind::fmmu_changed, attr(p, "Sm"), "Sm", dec(x.sm), dec(y.sm), x.pos, y.pos);
        r.value(ChangeKind::fmmu_changed, attr(p, "Su"), "Su", dec(x.su), dec(y.su), x.pos, y.pos);
        r.value(ChangeKind::fmmu_changed, attr(p, "OpOnly"), "OpOnly", flag(x.op_only), flag(y.op_only), x.pos, y.pos);
        compare_extras(r, p, x.extras, y.extras, x.pos, y.pos);
    }

    const std::size_t sus = std::max(a.sus.size(), b.sus.size());
    for (std::size_t i = 0; i < sus; ++i) {
        const std::string p = indexed("Su", std::to_string(i));
        if (i >= a.sus.size()) {
            r.add(ChangeKind::sync_unit_added, p, std::nullopt, b.sus[i].text, a.pos, b.sus[i].pos,
                  fmt::format("sync unit {} added", i));
            continue;
        }
        if (i >= b.sus.size()) {
            r.add(ChangeKind::sync_unit_removed, p, a.sus[i].text, std::nullopt, a.sus[i].pos, b.pos,
                  fmt::format("sync unit {} removed", i));
            continue;
        }
        const SyncUnit& x = a.sus[i];
        const SyncUnit& y = b.sus[i];
        r.value(ChangeKind::name_changed, p, "sync unit name", quote(x.text), quote(y.text), x.pos, y.pos);
        r.value(ChangeKind::sync_unit_changed, attr(p, "SeparateSu"), "SeparateSu", flag(x.separate_su), flag(y.separate_su),
                x.pos, y.pos);
        r.value(ChangeKind::sync_unit_changed, attr(p, "SeparateFrame"), "SeparateFrame", flag(x.separate_frame),
                flag(y.separate_frame), x.pos, y.pos);
        r.value(ChangeKind::sync_unit_changed, attr(p, "DependOnInputState"), "DependOnInputState", flag(x.depend_on_input_state),
                flag(y.depend_on_input_state), x.pos, y.pos);
        r.value(ChangeKind::sync_unit_changed, attr(p, "FrameRepeatSupport"), "FrameRepeatSupport", flag(x.frame_repeat_support),
                flag(y.frame_repeat_support), x.pos, y.pos);
        compare_extras(r, p, x.extras, y.extras, x.pos, y.pos);
    }
}

}  // namespace esi::diff_detail
