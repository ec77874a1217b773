// Rules of the dc area: distributed-clock operation modes (Dc/OpMode).
//
// AssignActivate is written by the master to ESC registers 0x0980 (low byte, cyclic unit control)
// and 0x0981 (high byte, activation): 0x0981 bit 0 activates the cyclic unit, bit 1 generates
// SYNC0, bit 2 SYNC1 (Beckhoff ESC datasheet section II, "Distributed Clocks"). The usual values,
// as Beckhoff's catalogues write them: #x0000 free run, #x0300 SYNC0, #x0700 SYNC0 + SYNC1, #x0730.
#include <limits>
#include <optional>
#include <string>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "check/queries.hpp"
#include "check/source_edit.hpp"
#include "esi/ethercat/dc.hpp"
#include "esi/number.hpp"

namespace esi::rules {

namespace {

// AssignActivate's activation bits (0x0981 in its high byte): the protocol layer's.
constexpr std::uint32_t activate_cyclic = ethercat::assign_activate::cyclic_operation;
constexpr std::uint32_t activate_sync0 = ethercat::assign_activate::sync0;
constexpr std::uint32_t activate_sync1 = ethercat::assign_activate::sync1;

std::string op_mode_label(const DcOpMode& mode) {
    return mode.name.empty() ? std::string("OpMode") : "OpMode '" + mode.name + "'";
}

// ---- dc-opmode-name, dc-opmode-duplicate ---------------------------------------------------

// The TwinCAT builds an OpMode is offered to: VendorSpecific/TwinCAT@UseFromBuildNo=N from build N
// on, @IgnoreFromBuildNo=N before build N. Beckhoff describes a changed OpMode as a pair of the
// same Name, one per build range (EL1xxx: DcSync up to build 1506 and from it), so only one of
// them is ever listed.
struct BuildRange {
    std::uint64_t first = 0;
    std::uint64_t end = std::numeric_limits<std::uint64_t>::max();  // exclusive
    [[nodiscard]] bool overlaps(const BuildRange& other) const { return first < other.end && other.first < end; }
};

BuildRange build_range(const DcOpMode& mode) {
    BuildRange range;
    const XmlElement* twincat = mode.extras.find("VendorSpecific/TwinCAT");
    if (!twincat) return range;
    const auto build = [&](std::string_view attribute) -> std::optional<std::uint64_t> {
        const XmlAttribute* a = twincat->attribute(attribute);
        if (!a) return std::nullopt;
        const ParsedNumber n = parse_number(a->value);
        return n.ok() && !n.value.negative ? std::optional<std::uint64_t>(n.value.magnitude) : std::nullopt;
    };
    if (const auto n = build("UseFromBuildNo")) range.first = *n;
    if (const auto n = build("IgnoreFromBuildNo")) range.end = *n;
    return range;
}

bool same_time(const std::optional<DcTime>& a, const std::optional<DcTime>& b) {
    if (!a || !b) return !a && !b;
    return a->value == b->value && a->factor == b->factor && a->input == b->input && a->output_delay_time == b->output_delay_time &&
           a->input_delay_time == b->input_delay_time;
}

bool same_extras(const Extras& a, const Extras& b) {
    if (a.attributes != b.attributes || a.elements.size() != b.elements.size()) return false;
    for (std::size_t i = 0; i < a.elements.size(); ++i)
        if (!same_content(a.elements[i], b.elements[i])) return false;
    return true;
}

// Two OpModes that say the same: name, description, AssignActivate, SYNC times, the Sm/Pdo
// lists and vendor-specific content (compared as content, not as text).
bool same_op_mode(const DcOpMode& a, const DcOpMode& b) {
    return a.name == b.name && a.desc == b.desc && a.has_assign_activate == b.has_assign_activate &&
           a.assign_activate == b.assign_activate && same_time(a.cycle_time_sync0, b.cycle_time_sync0) &&
           same_time(a.shift_time_sync0, b.shift_time_sync0) && same_time(a.cycle_time_sync1, b.cycle_time_sync1) &&
           same_time(a.shift_time_sync1, b.shift_time_sync1) && same_extras(a.extras, b.extras);
}

enum class NameClash { none, duplicate, conflict };

// How `mode` relates to the earlier OpModes of its device with the same Name: offered to other
// TwinCAT builds (none), repeated word for word (duplicate), or a different mode under the same
// Name (conflict, the worst one wins). `other` is set to the OpMode it clashes with.
NameClash name_clash(const Dc& dc, const DcOpMode& mode, const DcOpMode*& other) {
    NameClash clash = NameClash::none;
    const BuildRange range = build_range(mode);
    for (const auto& earlier : dc.op_modes) {
        if (&earlier == &mode) break;
        if (earlier.name != mode.name || !range.overlaps(build_range(earlier))) continue;
        if (!same_op_mode(earlier, mode)) {
            other = &earlier;
            return NameClash::conflict;
        }
        if (clash == NameClash::none) {
            clash = NameClash::duplicate;
            other = &earlier;
        }
    }
    return clash;
}

void check_name(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->dc) continue;
        for (const auto& mode : device->dc->op_modes) {
            if (mode.name.empty()) {
                context.report(mode.pos, "Dc OpMode has no Name; masters and modules (DcOpModeName) select an operation "
                                         "mode by its Name");
                continue;
            }
            const DcOpMode* other = nullptr;
            if (name_clash(*device->dc, mode, other) == NameClash::conflict)
                context.report(mode.pos, "Dc OpMode Name '" + mode.name + "' is used twice in this device for different "
                                                                          "settings; a master selecting it by name gets either one",
                               {context.note(other->pos, "the other OpMode with this Name")});
        }
    }
}

constexpr Rule dc_opmode_name{
    .id = "dc-opmode-name",
    .default_severity = Severity::error,
    .summary = "Dc OpMode without Name, or two different OpModes with the same Name",
    .rationale =
        "Masters list the operation modes by Name and modules select theirs through DcOpModeName, so every OpMode "
        "needs a Name that is unique within its device (ETG.2000 Dc/OpMode: Name is required); with two different "
        "modes of one Name, the master programs the SYNC signals of whichever it finds. OpModes of the same Name that "
        "TwinCAT offers to disjoint builds (VendorSpecific/TwinCAT@IgnoreFromBuildNo and @UseFromBuildNo, as "
        "Beckhoff's EL1xxx catalogues describe a changed mode) are distinct; an OpMode repeated word for word is "
        "dc-opmode-duplicate's warning.",
    .bad_example = "<OpMode><Name>DC</Name><AssignActivate>#x0300</AssignActivate>…</OpMode><OpMode><Name>DC</Name>"
                   "<AssignActivate>#x0700</AssignActivate>…</OpMode>",
    .good_example = "<OpMode><Name>DC</Name>...</OpMode><OpMode><Name>DC-Sync01</Name>...</OpMode>",
    .check = check_name,
};

void check_duplicate(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->dc) continue;
        for (const auto& mode : device->dc->op_modes) {
            const DcOpMode* other = nullptr;
            if (mode.name.empty() || name_clash(*device->dc, mode, other) != NameClash::duplicate) continue;
            context.report(mode.pos, "Dc OpMode '" + mode.name + "' repeats an earlier OpMode of this device word for word",
                           {context.note(other->pos, "the same OpMode")},
                           remove_identical_copy(document, other->pos, mode.pos, "remove the identical copy of the OpMode"));
        }
    }
}

constexpr Rule dc_opmode_duplicate{
    .id = "dc-opmode-duplicate",
    .default_severity = Severity::warning,
    .summary = "A Dc OpMode given twice with identical content",
    .rationale =
        "An OpMode repeated with the same Name, AssignActivate, SYNC times and Sm/Pdo lists (Beckhoff EL3632 lists its "
        "DcSync twice) offers the user the same choice twice; whichever a master picks, it programs the same "
        "settings (ETG.2000 Dc/OpMode). Harmless for the device, a copy-and-paste slip in the description: a warning. "
        "Different OpModes of one Name are dc-opmode-name's error.",
    .bad_example = "<OpMode><Name>DcSync</Name><AssignActivate>#x0730</AssignActivate>…</OpMode> twice",
    .good_example = "<OpMode><Name>DcSync</Name><AssignActivate>#x0730</AssignActivate>…</OpMode> once",
    .check = check_duplicate,
    .fix = "removes the repeat when it is a byte-identical copy of the first OpMode",
};

// ---- dc-assign-activate ---------------------------------------------------------------------

void check_assign_activate(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->dc) continue;
        for (const auto& mode : device->dc->op_modes) {
            if (!mode.has_assign_activate) {
                // A written but unreadable value already got xml-number-format.
                if (!mode.assign_activate_pos.known())
                    context.report(mode.pos, op_mode_label(mode) + " has no AssignActivate; write #x0000 for free run");
                continue;
            }
            const std::uint32_t aa = mode.assign_activate;
            const std::string value = format_hex(aa, 4);
            if (aa > 0xFFFF) {
                context.report(mode.assign_activate_pos, op_mode_label(mode) + ": AssignActivate " + value +
                                                             " does not fit the two registers 0x0980/0x0981 (16 bits)");
            } else if ((aa & (activate_sync0 | activate_sync1)) != 0 && (aa & activate_cyclic) == 0) {
                const std::string signals = (aa & activate_sync0) && (aa & activate_sync1) ? "SYNC0 and SYNC1"
                                            : (aa & activate_sync0)                         ? "SYNC0"
                                                                                            : "SYNC1";
                context.report(mode.assign_activate_pos,
                               op_mode_label(mode) + ": AssignActivate " + value + " asks for " + signals +
                                   " but does not set bit 8 (register 0x0981 bit 0, cyclic unit activation); the ESC "
                                   "generates no SYNC signal without it. Did you mean " +
                                   format_hex(aa | activate_cyclic, 4) + "?");
            }
        }
    }
}

constexpr Rule dc_assign_activate{
    .id = "dc-assign-activate",
    .default_severity = Severity::error,
    .summary = "AssignActivate that asks for SYNC signals without activating the cyclic unit",
    .rationale =
        "The high byte of AssignActivate goes to ESC register 0x0981: bit 0 activates the cyclic unit, bit 1 SYNC0, "
        "bit 2 SYNC1. SYNC0/SYNC1 bits without bit 0 (e.g. #x0200 instead of #x0300) generate no signal, so a device "
        "that waits for SYNC0 does not reach SAFE-OP (Beckhoff ESC datasheet section II, register 0x0981; Beckhoff's "
        "catalogues write #x0300 for SYNC0 and #x0700 for SYNC0+SYNC1, e.g. Beckhoff EL4xxx.xml in "
        "DiamondLightSource/ethercat etc/xml/; STÖBER ECS 5000 manual §11.5: with synchronisation active the inverter "
        "stays in PRE-OP without a valid SYNC0 cycle). A missing AssignActivate or one wider than 16 bits is reported "
        "too.",
    .bad_example = "<OpMode><Name>DC</Name><Desc>DC-Synchron</Desc><AssignActivate>#x0200</AssignActivate></OpMode>",
    .good_example = "<OpMode><Name>DC</Name><Desc>DC-Synchron</Desc><AssignActivate>#x0300</AssignActivate></OpMode>",
    .check = check_assign_activate,
};

// ---- dc-assign-activate-reserved ------------------------------------------------------------

// Register 0x0980 (cyclic unit control, AssignActivate's low byte): bit 0 hands the cyclic unit to
// the PDI, bits 4 and 5 latch units 0 and 1; bits 1-3 and 6-7 are reserved (ESC datasheet section
// II, register 0x0980).
constexpr std::uint32_t cyclic_unit_control_reserved = 0x00CE;

void check_assign_activate_reserved(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->dc) continue;
        for (const auto& mode : device->dc->op_modes) {
            if (!mode.has_assign_activate || mode.assign_activate > 0xFFFF) continue;  // dc-assign-activate's
            const std::uint32_t reserved = mode.assign_activate & cyclic_unit_control_reserved;
            if (reserved == 0) continue;
            context.report(mode.assign_activate_pos,
                           op_mode_label(mode) + ": AssignActivate " + format_hex(mode.assign_activate, 4) + " sets " +
                               format_hex(reserved, 2) + " in its low byte, reserved bits of register 0x0980 (only "
                               "bit 0, cyclic unit to PDI, and bits 4-5, latch units to PDI, have a meaning)");
        }
    }
}

constexpr Rule dc_assign_activate_reserved{
    .id = "dc-assign-activate-reserved",
    .default_severity = Severity::error,
    .summary = "AssignActivate with reserved bits of register 0x0980 (its low byte)",
    .rationale =
        "The master writes AssignActivate's low byte into ESC register 0x0980, cyclic unit control: bit 0 gives the "
        "SYNC unit to the PDI, bits 4 and 5 the latch units; bits 1-3 and 6-7 are reserved and must be written 0 "
        "(Beckhoff ESC datasheet section II, register 0x0980). The values in use are #x00, #x01, #x20 and #x30 "
        "(Beckhoff's catalogues: #x0730, #x0301, #x0120, #x0030); any other bit is a typing slip, most often a "
        "SYNC activation shifted into the wrong byte (#x0003 for #x0300), and gives undefined ESC behaviour.",
    .bad_example = "<OpMode><Name>DC</Name><AssignActivate>#x0003</AssignActivate></OpMode>",
    .good_example = "<OpMode><Name>DC</Name><AssignActivate>#x0300</AssignActivate></OpMode>",
    .check = check_assign_activate_reserved,
};

// ---- dc-sync1-without-sync0 -----------------------------------------------------------------

void check_sync1_without_sync0(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->dc) continue;
        for (const auto& mode : device->dc->op_modes) {
            if (!mode.has_assign_activate || mode.assign_activate > 0xFFFF) continue;
            const std::uint32_t aa = mode.assign_activate;
            if ((aa & activate_cyclic) == 0 || (aa & activate_sync1) == 0 || (aa & activate_sync0) != 0) continue;
            context.report(mode.assign_activate_pos,
                           op_mode_label(mode) + ": AssignActivate " + format_hex(aa, 4) +
                               " generates SYNC1 but not SYNC0; SYNC1 is timed from the SYNC0 pulses (its cycle time "
                               "is the delay after SYNC0), so activate both (" + format_hex(aa | activate_sync0, 4) + ")");
        }
    }
}

constexpr Rule dc_sync1_without_sync0{
    .id = "dc-sync1-without-sync0",
    .default_severity = Severity::warning,
    .summary = "AssignActivate that generates SYNC1 without SYNC0",
    .rationale =
        "Register 0x0981 bit 1 generates SYNC0 and bit 2 SYNC1 (ESC datasheet section II). SYNC1 is derived from "
        "SYNC0: the SYNC1 cycle time (0x09A4) is the delay after a SYNC0 pulse, and CycleTimeSync1 in the ESI and "
        "the SII DC category (ETG.2010) count in SYNC0 cycles. An OpMode with SYNC1 alone (#x0500) is a slip for "
        "#x0700: every SYNC1 OpMode of Beckhoff's catalogues activates SYNC0 too (#x0700, #x0730), and SOEM's "
        "ecx_dcsync01 always activates both. Whether the ESC still emits SYNC1 depends on the ESC, so a warning.",
    .bad_example = "<OpMode><Name>DC</Name><AssignActivate>#x0500</AssignActivate></OpMode>",
    .good_example = "<OpMode><Name>DC</Name><AssignActivate>#x0700</AssignActivate></OpMode>",
    .check = check_sync1_without_sync0,
};

// ---- dc-opmode-sm-reference -----------------------------------------------------------------

std::optional<std::uint64_t> number_of(std::string_view text) {
    const ParsedNumber n = parse_number(text);
    return n.ok() && !n.value.negative ? std::optional<std::uint64_t>(n.value.magnitude) : std::nullopt;
}

void check_opmode_sm_reference(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->dc) continue;
        for (const auto& mode : device->dc->op_modes) {
            for (const XmlElement& sm : mode.extras.elements) {
                if (sm.name != "Sm") continue;
                const XmlAttribute* no = sm.attribute("No");
                const std::optional<std::uint64_t> number = no ? number_of(no->value) : std::nullopt;
                const std::uint64_t sm_number = number.value_or(0);
                const std::string sm_name = number ? "SM" + std::to_string(sm_number) : std::string("its SM");
                if (number && sm_number >= device->sms.size()) {
                    context.report(sm.pos, op_mode_label(mode) + ": Sm No=\"" + no->value + "\" names " + sm_name +
                                               ", but the device has " + std::to_string(device->sms.size()) + " SyncManagers");
                    continue;
                }
                // A slot device's PDOs come from the modules plugged into it.
                if (device->slots) continue;
                for (const XmlElement& pdo : sm.children) {
                    if (pdo.name != "Pdo") continue;
                    const std::optional<std::uint64_t> index = number_of(pdo.text);
                    if (!index || *index > 0xFFFF || device->find_pdo(static_cast<std::uint32_t>(*index))) continue;
                    context.report(pdo.pos, op_mode_label(mode) + ": Pdo " + format_hex(*index, 4) +
                                                " assigned to " + sm_name +
                                                " is not a PDO of the device; a tool selecting this OpMode cannot assign it");
                }
            }
        }
    }
}

constexpr Rule dc_opmode_sm_reference{
    .id = "dc-opmode-sm-reference",
    .default_severity = Severity::warning,
    .summary = "A Dc OpMode's Sm names a missing SyncManager, or its Pdo a PDO the device does not have",
    .rationale =
        "An OpMode can state the PDO assignment that goes with it: Dc/OpMode/Sm@No names the SyncManager (the n-th Sm "
        "element) and its Pdo children the PDOs a configuration tool assigns to it when the user selects the mode "
        "(ETG.2000 Dc/OpMode/Sm). A missing SM or PDO leaves the tool without the assignment the mode needs; Beckhoff's "
        "EL2262 lists #x1B02 for SM2 where the device's PDO on SM2 is #x1702. Masters that do not follow OpMode "
        "assignments (and the SII, which has no place for them) are unaffected, so a warning. Slot devices, whose "
        "PDOs come from their modules, are only checked for the SM.",
    .bad_example = "<OpMode><Name>DcSync</Name>…<Sm No=\"2\"><Pdo>#x1B02</Pdo></Sm></OpMode> (no PDO #x1B02)",
    .good_example = "<OpMode><Name>DcSync</Name>…<Sm No=\"2\"><Pdo>#x1702</Pdo></Sm></OpMode>",
    .check = check_opmode_sm_reference,
};

// ---- dc-cycle-time --------------------------------------------------------------------------

void check_cycle_time(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->dc) continue;
        for (const auto& mode : device->dc->op_modes) {
            for (const auto* t : {&mode.cycle_time_sync0, &mode.cycle_time_sync1}) {
                if (*t && (*t)->value < 0)
                    context.report((*t)->pos, op_mode_label(mode) + ": " +
                                                  (t == &mode.cycle_time_sync0 ? "CycleTimeSync0" : "CycleTimeSync1") +
                                                  " is " + std::to_string((*t)->value) +
                                                  " ns; a cycle time cannot be negative (the ESC cycle registers are "
                                                  "unsigned)");
            }
            if (!mode.has_assign_activate || mode.assign_activate > 0xFFFF) continue;
            const bool sync0 = (mode.assign_activate & (activate_cyclic | activate_sync0)) == (activate_cyclic | activate_sync0);
            const bool sync1 = (mode.assign_activate & (activate_cyclic | activate_sync1)) == (activate_cyclic | activate_sync1);
            struct Timing {
                const std::optional<DcTime>& time;
                const char* name;
                bool active;
                const char* signal;
            };
            const Timing timings[] = {
                {mode.cycle_time_sync0, "CycleTimeSync0", sync0, "SYNC0 (bits 8 and 9)"},
                {mode.shift_time_sync0, "ShiftTimeSync0", sync0, "SYNC0 (bits 8 and 9)"},
                {mode.cycle_time_sync1, "CycleTimeSync1", sync1, "SYNC1 (bits 8 and 10)"},
                {mode.shift_time_sync1, "ShiftTimeSync1", sync1, "SYNC1 (bits 8 and 10)"},
            };
            for (const auto& t : timings) {
                if (!t.time || t.active || t.time->value <= 0) continue;
                context.report(t.time->pos, op_mode_label(mode) + ": " + t.name + " is " + std::to_string(t.time->value) +
                                                " ns but AssignActivate " + format_hex(mode.assign_activate, 4) +
                                                " does not activate " + t.signal +
                                                "; the time is never used. Activate the signal or write 0");
            }
        }
    }
}

constexpr Rule dc_cycle_time{
    .id = "dc-cycle-time",
    .default_severity = Severity::warning,
    .summary = "DC times for a SYNC signal that is not activated, or negative cycle times",
    .rationale =
        "CycleTimeSync0/ShiftTimeSync0 configure SYNC0 and CycleTimeSync1/ShiftTimeSync1 SYNC1 (ESC registers "
        "0x09A0-0x09A7; ETG.2010 DC category). A non-zero time for a signal AssignActivate does not activate is never "
        "used and usually means the wrong AssignActivate was copied (e.g. a SYNC1 shift with #x0300); a negative "
        "cycle time cannot be programmed at all. Factors are not checked: Beckhoff writes negative factors as "
        "dividers of the bus cycle.",
    .bad_example =
        "<OpMode><Name>DC</Name><AssignActivate>#x0300</AssignActivate><CycleTimeSync0 Factor=\"1\">0</CycleTimeSync0>"
        "<ShiftTimeSync0>0</ShiftTimeSync0><CycleTimeSync1 Factor=\"1\">0</CycleTimeSync1><ShiftTimeSync1>100000</"
        "ShiftTimeSync1></OpMode>",
    .good_example =
        "<OpMode><Name>DC</Name><AssignActivate>#x0700</AssignActivate><CycleTimeSync0 Factor=\"1\">0</CycleTimeSync0>"
        "<ShiftTimeSync0>0</ShiftTimeSync0><CycleTimeSync1 Factor=\"1\">0</CycleTimeSync1><ShiftTimeSync1>100000</"
        "ShiftTimeSync1></OpMode>",
    .check = check_cycle_time,
};

}  // namespace

void add_dc(std::vector<Rule>& out) {
    out.insert(out.end(), {
        dc_opmode_name,
        dc_opmode_duplicate,
        dc_assign_activate,
        dc_assign_activate_reserved,
        dc_sync1_without_sync0,
        dc_opmode_sm_reference,
        dc_cycle_time,
    });
}

}  // namespace esi::rules
