// Rules of the sm area: SyncManager ControlByte, order, sizes, address ranges and 0x1C00.
//
// The ControlByte is written to ESC register 0x0804 + 8n (ETG.1000.4; Beckhoff ESC datasheet
// section II "SyncManager Control"): bits 1:0 operation mode (00 buffered = 3 buffers, 10 mailbox
// = 1 buffer, 01/11 reserved), bits 3:2 direction (00 read: ECAT reads, PDI writes; 01 write:
// ECAT writes, PDI reads; 1x reserved), bit 4 ECAT event, bit 5 PDI (AL event) interrupt, bit 6
// watchdog trigger, bit 7 reserved. The Sm order gives the SM number: the n-th Sm is SMn.
//
// The file stays whole although it is past 500 lines: it is the sm family's catalogue, each rule's
// Rule constant right below its check (areas.hpp), and the rules share the ControlByte helpers
// below (the SM memory layout they share with rules_sm_esc.cpp is in sm_memory.hpp); a split by
// topic would separate rules from the helpers they use together.
#include <algorithm>
#include <string>

#include "check/areas.hpp"
#include "check/queries.hpp"
#include "check/rule_cache.hpp"
#include "check/sm_memory.hpp"
#include "check/sm_roles.hpp"
#include "esi/number.hpp"

namespace esi::rules {

namespace {

std::string sm_label(const SyncManager& sm, std::size_t number) {
    std::string label = "SM" + std::to_string(number);
    if (!sm.type.empty()) label += " '" + sm.type + "'";
    return label;
}

std::string byte_hex(std::uint32_t value) { return format_hex(value, 2); }
std::string address_hex(std::uint64_t value) { return format_hex(value, 4); }

bool role_is_write(SmRole role) { return role == SmRole::mailbox_out || role == SmRole::outputs; }
bool role_is_mailbox(SmRole role) { return role == SmRole::mailbox_out || role == SmRole::mailbox_in; }

bool mode_reserved(std::uint32_t control_byte) { return (control_byte & 0x03) == 0x01 || (control_byte & 0x03) == 0x03; }
bool direction_reserved(std::uint32_t control_byte) { return (control_byte & 0x08) != 0; }

std::string_view typical_control_byte(SmRole role) {
    switch (role) {
        case SmRole::mailbox_out: return "#x26";
        case SmRole::mailbox_in: return "#x22";
        case SmRole::outputs: return "#x24 or #x64";
        case SmRole::inputs: return "#x20";
        case SmRole::unknown: break;
    }
    return "";
}

// ---- sm-direction-mismatch ------------------------------------------------------------------

void check_direction(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            const SmRole role = text_sm_role(sm);
            if (role == SmRole::unknown || !sm.control_byte || direction_reserved(*sm.control_byte)) continue;
            const bool write = control_byte_is_write(*sm.control_byte);
            if (write == role_is_write(role)) continue;
            context.report(sm.pos, sm_label(sm, n) + " has ControlByte " + byte_hex(*sm.control_byte) + ", which is a " +
                                       (write ? "write (master -> slave)" : "read (slave -> master)") + " " +
                                       (role_is_mailbox(role) ? "mailbox" : "buffer") + "; " + sm.type + " needs " +
                                       std::string(typical_control_byte(role)));
        }
    }
}

constexpr Rule sm_direction_mismatch{
    .id = "sm-direction-mismatch",
    .default_severity = Severity::error,
    .summary = "SM text and ControlByte direction disagree",
    .rationale =
        "ControlByte bits 3:2 set the SyncManager direction (00: the master reads, 01: the master writes; ESC "
        "register 0x0804+8n, ETG.1000.4). MBoxOut and Outputs carry data from the master to the slave and need the "
        "write direction (#x26, #x24, #x64); MBoxIn and Inputs need the read direction (#x22, #x20). A swapped "
        "direction makes the ESC refuse the master's writes or the PDI's updates, and the device stays in PRE-OP with "
        "an SM configuration error (SOES tutorial SM table; OpenEtherCATsociety/SOEM #247, where the maintainer lists "
        "the canonical #x26/#x22/#x24/#x20 block; SOES soes/esc.c ESC_checkSM23 keeps the device in PRE-OP when the "
        "SM2/SM3 control bytes differ from its own).",
    .bad_example = "<Sm StartAddress=\"#x1100\" ControlByte=\"#x20\" Enable=\"1\">Outputs</Sm>",
    .good_example = "<Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm>",
    .check = check_direction,
};

// ---- sm-mailbox-mode ------------------------------------------------------------------------

void check_mailbox_mode(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            const SmRole role = role_from_text(sm.type);
            if (!role_is_mailbox(role) || !sm.control_byte || (*sm.control_byte & 0x03) != 0x00) continue;
            context.report(sm.pos, sm_label(sm, n) + " has ControlByte " + byte_hex(*sm.control_byte) +
                                       ", which selects buffered (3-buffer) mode; a mailbox SM needs mailbox mode "
                                       "(bits 1:0 = 10), e.g. " +
                                       std::string(typical_control_byte(role)));
        }
    }
}

constexpr Rule sm_mailbox_mode{
    .id = "sm-mailbox-mode",
    .default_severity = Severity::error,
    .summary = "A mailbox SM whose ControlByte selects buffered mode",
    .rationale =
        "MBoxOut and MBoxIn must run in mailbox (single-buffer, handshake) mode, ControlByte bits 1:0 = 10: #x26 for "
        "the master's requests and #x22 for the slave's answers. In buffered (3-buffer) mode the ESC overwrites "
        "unread messages and occupies three times the size (ESC register 0x0804+8n; SOES tutorial; "
        "OpenEtherCATsociety/SOEM #247 lists the canonical #x26/#x22 pair; in 95 public ESI files, Beckhoff's "
        "catalogues in DiamondLightSource/ethercat among them, 500 MBoxOut and 500 MBoxIn SMs use exactly these; the "
        "only others are in the BogusServo.xml test file of zultron/hw_device_mgr).",
    .bad_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x24\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>",
    .good_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>",
    .check = check_mailbox_mode,
};

// ---- sm-control-byte-reserved ---------------------------------------------------------------

void check_control_byte_reserved(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            if (!sm.control_byte) continue;
            const std::uint32_t cb = *sm.control_byte;
            std::string what;
            if (cb > 0xFF) what = "does not fit the 8-bit register";
            else if (mode_reserved(cb)) what = "sets the reserved operation mode " + std::to_string((cb >> 1) & 1) + std::to_string(cb & 1) + " in bits 1:0";
            else if (direction_reserved(cb)) what = "sets the reserved direction 1" + std::to_string((cb >> 2) & 1) + " in bits 3:2";
            else if (cb & 0x80) what = "sets the reserved bit 7";
            else continue;
            std::string reg = format_hex(0x0804 + 8 * n, 4);
            reg.replace(0, 2, "0x");
            context.report(sm.pos, sm_label(sm, n) + " has ControlByte " + byte_hex(cb) + ", which " + what +
                                       " of its control register " + reg);
        }
    }
}

constexpr Rule sm_control_byte_reserved{
    .id = "sm-control-byte-reserved",
    .default_severity = Severity::error,
    .summary = "ControlByte with reserved bits or values",
    .rationale =
        "The SyncManager control register (0x0804+8n) reserves operation modes 01 and 11 (bits 1:0), directions 10 "
        "and 11 (bits 3:2) and bit 7 (ETG.1000.4; Beckhoff ESC datasheet section II). A master copies the ControlByte "
        "into the register as it is, so a reserved value gives undefined ESC behaviour. Values above #xFF do not fit "
        "the register at all.",
    .bad_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x33\" Enable=\"1\">MBoxOut</Sm>",
    .good_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" Enable=\"1\">MBoxOut</Sm>",
    .check = check_control_byte_reserved,
};

// ---- sm-mailbox-position --------------------------------------------------------------------

void check_mailbox_position(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            const SmRole role = device_sm_role(*device, sm);
            if (role == SmRole::mailbox_out && n != 0)
                context.report(sm.pos, sm_label(sm, n) + " is the mailbox out SM, which must be SM0 (the first Sm)");
            else if (role == SmRole::mailbox_in && n != 1)
                context.report(sm.pos, sm_label(sm, n) + " is the mailbox in SM, which must be SM1 (the second Sm)");
        }
    }
}

constexpr Rule sm_mailbox_position{
    .id = "sm-mailbox-position",
    .default_severity = Severity::error,
    .summary = "Mailbox SMs not at SM0 (out) and SM1 (in)",
    .rationale =
        "The standard mailbox uses SM0 for master -> slave (MBoxOut) and SM1 for slave -> master (MBoxIn): the SII "
        "standard mailbox words 0x18-0x1B and 0x1C00:01/02 describe exactly these two, and masters program SM0 and SM1 "
        "as the mailbox from those words whatever the description's order (SOEM ecx_config_init sets SM[0]/SM[1] from "
        "the SII mailbox offsets; SOES tutorial; the item C series and Afag SE-Power EtherCAT manuals §6.1.1: SM0 is "
        "the mailbox for incoming SDOs, SM1 the one for outgoing SDOs). A device describing its mailbox on other SMs "
        "is configured differently from what it declares: an error. The n-th Sm element is SMn.",
    .bad_example =
        "<Sm ...>Outputs</Sm><Sm ...>Inputs</Sm><Sm ... ControlByte=\"#x26\">MBoxOut</Sm><Sm ... "
        "ControlByte=\"#x22\">MBoxIn</Sm>",
    .good_example =
        "<Sm ... ControlByte=\"#x26\">MBoxOut</Sm><Sm ... ControlByte=\"#x22\">MBoxIn</Sm><Sm ...>Outputs</Sm><Sm "
        "...>Inputs</Sm>",
    .check = check_mailbox_position,
};

// ---- sm-overlap -----------------------------------------------------------------------------

struct SmRange {
    std::size_t number;
    std::uint64_t start;
    std::uint64_t size;  // one buffer
    std::uint64_t end;   // exclusive, all buffers
};

std::string describe_range(const Device& device, const SmRange& r) {
    const SyncManager& sm = device.sms[r.number];
    std::string text = sm_label(sm, r.number) + " (" + address_hex(r.start) + ", " + std::to_string(r.size) + " byte" +
                       (r.size == 1 ? "" : "s");
    if (r.end - r.start != r.size) text += ", 3 buffers: " + address_hex(r.start) + ".." + address_hex(r.end - 1);
    return text + ")";
}

void check_overlap(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        std::vector<SmRange> ranges;
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            if (!sm.start_address || (sm.is_virtual && *sm.is_virtual)) continue;
            const std::uint64_t size = effective_size(*device, n);
            if (size == 0) continue;
            ranges.push_back({n, *sm.start_address, size, *sm.start_address + size * (occupies_three_buffers(*device, sm, size) ? 3 : 1)});
        }
        std::sort(ranges.begin(), ranges.end(), [](const SmRange& a, const SmRange& b) {
            return a.start != b.start ? a.start < b.start : a.number < b.number;
        });
        const SmRange* reach = nullptr;  // the range that reaches furthest so far
        for (const auto& r : ranges) {
            if (reach && r.start < reach->end) {
                context.report(device->sms[r.number].pos,
                               describe_range(*device, r) + " overlaps " + describe_range(*device, *reach) +
                                   "; the ESC would let two SyncManagers share memory",
                               {context.note(device->sms[reach->number].pos, "the other SyncManager")});
            }
            if (!reach || r.end > reach->end) reach = &r;
        }
    }
}

constexpr Rule sm_overlap{
    .id = "sm-overlap",
    .default_severity = Severity::error,
    .summary = "Two SyncManagers whose memory ranges overlap",
    .rationale =
        "Each SyncManager owns [StartAddress, StartAddress + size) of ESC memory, and a buffered process-data SM "
        "(ControlByte bits 1:0 = 00) owns three consecutive buffers of that size (ESC datasheet '3-buffer mode'); the "
        "master only writes the first address to the ESC. Overlapping ranges corrupt each other's data (SOES "
        "soes/esc.c ESC_checkSM23 refuses the state change when SM2's three buffers reach into SM3). A process-data "
        "SM's size is that of the PDOs assigned to it by default, since the master computes it from them, else "
        "DefaultSize; a mailbox SM counts once (a buffered mailbox is sm-mailbox-mode's finding). SMs below 0x1000, "
        "in the register area (Beckhoff terminals put 1-byte buffered SMs on the digital I/O bytes 0x0F00, 0x0F01), "
        "count once as well, and so do 1-byte SMs of a device whose PDI is digital I/O (ConfigData byte 0 = 0x04, PDI "
        "control register 0x0140): the ESC moves those I/O bytes itself, one byte each.",
    .bad_example =
        "<Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" DefaultSize=\"64\" Enable=\"1\">Outputs</Sm> "
        "<Sm StartAddress=\"#x1140\" ControlByte=\"#x20\" DefaultSize=\"64\" Enable=\"1\">Inputs</Sm>",
    .good_example =
        "<Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" DefaultSize=\"64\" Enable=\"1\">Outputs</Sm> "
        "<Sm StartAddress=\"#x1200\" ControlByte=\"#x20\" DefaultSize=\"64\" Enable=\"1\">Inputs</Sm>",
    .check = check_overlap,
};

// ---- sm-size-zero ---------------------------------------------------------------------------

void check_size_zero(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        // Slot devices get their PDOs (and so their SM sizes) from the plugged modules.
        if (device->slots) continue;
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            if (!sm.default_size || *sm.default_size != 0 || !sm.enable || (*sm.enable & 1) == 0) continue;
            if (sm.is_virtual && *sm.is_virtual) continue;
            if (default_pdo_bytes(*device, n) != 0) continue;  // the master sizes it from the PDOs
            context.report(sm.pos, sm_label(sm, n) + " is enabled (Enable=" + std::to_string(*sm.enable) +
                                       ") with DefaultSize 0 and no PDO assigned to it by default; ESCs reject an "
                                       "enabled SyncManager of length 0. Write Enable=\"0\" or give it a size");
        }
    }
}

constexpr Rule sm_size_zero{
    .id = "sm-size-zero",
    .default_severity = Severity::warning,
    .summary = "Enabled SM with DefaultSize 0 and no default PDOs",
    .rationale =
        "An SM that is enabled but ends up with length 0 is rejected by the ESC or the slave firmware (AL status "
        "0x001D/0x001E 'invalid output/input configuration'); masters that take the SII values as they are run into "
        "it (ethercrab-rs/ethercrab #354: PS2001, EL6614, ELM3004; OpenEtherCATsociety/SOEM #246). When PDOs are "
        "assigned to the SM by default the master computes the length from them, so the rule fires only when none "
        "are. Write Enable=\"0\" for an SM that starts empty.",
    .bad_example = "<Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" DefaultSize=\"0\" Enable=\"1\">Outputs</Sm>",
    .good_example = "<Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" DefaultSize=\"0\" Enable=\"0\">Outputs</Sm>",
    .check = check_size_zero,
};

// ---- sm-default-size-pdo --------------------------------------------------------------------

void check_default_size_pdo(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        // Slot devices get their PDOs (and so their SM sizes) from the plugged modules.
        if (device->slots) continue;
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            if (!sm.default_size || *sm.default_size == 0 || sm.is_virtual.value_or(false)) continue;
            const SmRole role = device_sm_role(*device, sm);
            if (role != SmRole::outputs && role != SmRole::inputs) continue;
            // A lower bound: an oversampling PDO (OSFac) is counted once.
            const std::uint64_t pdo_bytes = default_pdo_bytes(*device, n);
            if (pdo_bytes <= *sm.default_size) continue;
            context.report(sm.pos, sm_label(sm, n) + " has DefaultSize " + std::to_string(*sm.default_size) +
                                       " but the PDOs assigned to it by default (Sm=\"" + std::to_string(n) + "\") carry at least " +
                                       std::to_string(pdo_bytes) + " bytes; a tool that starts the SM with DefaultSize cuts "
                                       "the process data short");
        }
    }
}

constexpr Rule sm_default_size_pdo{
    .id = "sm-default-size-pdo",
    .default_severity = Severity::warning,
    .summary = "A process-data SM whose DefaultSize is smaller than its default PDOs",
    .rationale =
        "DefaultSize is the length an SM starts with (ETG.2000 Sm@DefaultSize; the SII builder copies it into the SII "
        "SyncM category). Masters size a process-data SM from the PDOs assigned to it, so they still exchange all of "
        "it (SOEM recomputes the SM length from the PDO mapping; TwinCAT from the PDO assignment), but a tool that "
        "takes the SyncM category as it stands cuts the data short, and the value is plainly stale: Beckhoff's "
        "EL4102 revision 0x03F8 has DefaultSize 2 for 4 bytes of outputs, revision 0x03F9 has 4. A warning. A "
        "DefaultSize larger than the PDOs is not reported: it is the room the firmware reserves (the largest mapping "
        "it accepts). DefaultSize 0 is sm-size-zero's concern, and slot devices take their PDOs from modules.",
    .bad_example =
        "<Sm DefaultSize=\"2\" StartAddress=\"#x1100\" ControlByte=\"#x24\" Enable=\"1\">Outputs</Sm> … <RxPdo Sm=\"2\"> "
        "(two INT entries)",
    .good_example =
        "<Sm DefaultSize=\"4\" StartAddress=\"#x1100\" ControlByte=\"#x24\" Enable=\"1\">Outputs</Sm> … <RxPdo Sm=\"2\"> "
        "(two INT entries)",
    .check = check_default_size_pdo,
};

// ---- sm-size-range --------------------------------------------------------------------------

void check_size_range(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            const auto& lo = sm.min_size;
            const auto& hi = sm.max_size;
            const auto& def = sm.default_size;
            std::string problem;
            if (lo && hi && *lo > *hi)
                problem = "MinSize " + std::to_string(*lo) + " is larger than MaxSize " + std::to_string(*hi);
            else if (def && lo && *def < *lo)
                problem = "DefaultSize " + std::to_string(*def) + " is below MinSize " + std::to_string(*lo);
            else if (def && hi && *def > *hi)
                problem = "DefaultSize " + std::to_string(*def) + " is above MaxSize " + std::to_string(*hi);
            else continue;
            context.report(sm.pos, sm_label(sm, n) + ": " + problem);
        }
    }
}

constexpr Rule sm_size_range{
    .id = "sm-size-range",
    .default_severity = Severity::warning,
    .summary = "SM sizes outside MinSize <= DefaultSize <= MaxSize",
    .rationale =
        "MinSize and MaxSize bound the length a user may configure in a configuration tool, and DefaultSize is what "
        "the master starts the SyncManager with (ETG.2000 Sm attributes; the SII builder writes DefaultSize into the "
        "SII mailbox words, which IgH and SOEM take). A default outside the bounds, or MinSize above MaxSize, leaves no "
        "consistent range to edit in, and configuration tools clamp differently; the device still runs with "
        "DefaultSize (Beckhoff FC1100: MaxSize 256 with DefaultSize 1024, the SM addresses laid out for 1024). "
        "Inconsistent but tolerated: a warning. A DefaultSize that does not fit the ESC memory is sm-overlap's error.",
    .bad_example =
        "<Sm MinSize=\"34\" MaxSize=\"128\" DefaultSize=\"256\" StartAddress=\"#x1000\" ControlByte=\"#x26\" "
        "Enable=\"1\">MBoxOut</Sm>",
    .good_example =
        "<Sm MinSize=\"34\" MaxSize=\"256\" DefaultSize=\"256\" StartAddress=\"#x1000\" ControlByte=\"#x26\" "
        "Enable=\"1\">MBoxOut</Sm>",
    .check = check_size_range,
};

// ---- sm-mailbox-size ------------------------------------------------------------------------

// A mailbox message is a 6-byte mailbox header plus the protocol's data; an expedited CoE SDO
// needs 6 + 2 (CoE header) + 8 (SDO) = 16 bytes (ETG.1000.6 mailbox and SDO frame layout; STÖBER
// ECS 5000 manual §7.2 gives the same 6 + 2 + 8 layout).
constexpr std::uint32_t minimum_mailbox_size = 16;

void check_mailbox_size(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            if (!role_is_mailbox(device_sm_role(*device, sm))) continue;
            if (!sm.default_size) {
                context.report(sm.pos, sm_label(sm, n) +
                                           " is a mailbox SM without DefaultSize; the SII standard mailbox size (words "
                                           "0x18-0x1B) and the master's mailbox length come from it");
            } else if (*sm.default_size < minimum_mailbox_size) {
                context.report(sm.pos, sm_label(sm, n) + " has a mailbox of " + std::to_string(*sm.default_size) +
                                           " bytes; a mailbox needs at least " + std::to_string(minimum_mailbox_size) +
                                           " (6-byte mailbox header, 2-byte CoE header, 8-byte SDO)");
            }
        }
    }
}

constexpr Rule sm_mailbox_size{
    .id = "sm-mailbox-size",
    .default_severity = Severity::error,
    .summary = "Mailbox SM without DefaultSize or too small",
    .rationale =
        "The standard mailbox offset and size in SII words 0x18-0x1B come from the MBoxOut/MBoxIn SMs' StartAddress "
        "and DefaultSize (ETG.2010; CTT TF-1300 2-12), so a mailbox SM without DefaultSize yields a mailbox of 0 "
        "bytes, which masters take as no mailbox at all (SOEM configures the mailbox SMs only when the SII mailbox "
        "length is above 0). A mailbox message is a 6-byte header plus data; an expedited CoE SDO needs 6 + 2 + 8 = 16 "
        "bytes (ETG.1000.6 mailbox and SDO layout; STÖBER ECS 5000 manual §7.2 'Mailbox-Header 6 Byte, CoE-Header 2 "
        "Byte, Expedited SDO-Message 8 Byte'). Either way no mailbox protocol works: an error.",
    .bad_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" Enable=\"1\">MBoxOut</Sm>",
    .good_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>",
    .check = check_mailbox_size,
};

// ---- sm-1c00-mismatch -----------------------------------------------------------------------

// 0x1C00 "Sync manager communication type" (ETG.1000.6 Table 67): sub n describes SM n-1 with
// 0 unused, 1 mailbox receive (master -> slave), 2 mailbox send, 3 process data output, 4 input.
std::uint64_t communication_type(SmRole role) {
    switch (role) {
        case SmRole::mailbox_out: return 1;
        case SmRole::mailbox_in: return 2;
        case SmRole::outputs: return 3;
        case SmRole::inputs: return 4;
        case SmRole::unknown: break;
    }
    return 0;
}

std::string_view communication_type_name(std::uint64_t type) {
    switch (type) {
        case 0: return "unused";
        case 1: return "mailbox receive (master -> slave)";
        case 2: return "mailbox send (slave -> master)";
        case 3: return "process data output";
        case 4: return "process data input";
        default: return "not a communication type";
    }
}

void check_1c00(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        const Dictionary* dictionary = device->dictionary();
        if (!dictionary) continue;
        const Object* object = dictionary->find_object(0x1C00);
        if (!object) continue;
        const ObjectLayout& layout = context.cache().objects(dictionary).layout(*object);
        for (const auto& entry : layout.entries) {
            if (entry.subindex == 0 || entry.subindex > 32) continue;
            const std::optional<std::uint64_t> value = default_integer(entry);
            if (!value) continue;
            const SourcePos at = default_pos(entry).known() ? default_pos(entry) : object->pos;
            const std::size_t number = entry.subindex - 1;
            const std::string where = "0x1C00:" + std::string(entry.subindex < 10 ? "0" : "") + std::to_string(entry.subindex);
            if (*value > 4) {
                context.report(at, where + " defaults to " + std::to_string(*value) + ", which is " +
                                       std::string(communication_type_name(*value)) + " (0..4)");
                continue;
            }
            if (*value == 0) continue;  // unused is always allowed
            if (number >= device->sms.size()) {
                context.report(at, where + " defaults to " + std::to_string(*value) + " (" +
                                       std::string(communication_type_name(*value)) + ") but the device has no SM" +
                                       std::to_string(number));
                continue;
            }
            const SyncManager& sm = device->sms[number];
            const SmRole role = device_sm_role(*device, sm);
            if (role == SmRole::unknown) continue;
            const std::uint64_t expected = communication_type(role);
            if (expected == *value) continue;
            context.report(at,
                           where + " defaults to " + std::to_string(*value) + " (" + std::string(communication_type_name(*value)) +
                               ") but " + sm_label(sm, number) + " is " + std::string(to_string(role)) + ", type " +
                               std::to_string(expected) + " (" + std::string(communication_type_name(expected)) + ")",
                           {context.note(sm.pos, "the SyncManager")});
        }
    }
}

constexpr Rule sm_1c00_mismatch{
    .id = "sm-1c00-mismatch",
    .default_severity = Severity::warning,
    .summary = "0x1C00 communication types disagree with the Sm list",
    .rationale =
        "0x1C00 sub n gives the type of SM n-1: 1 mailbox receive, 2 mailbox send, 3 process data output, 4 process "
        "data input, 0 unused (ETG.1000.6 object 0x1C00; the item C series and Afag SE-Power EtherCAT manuals "
        "§6.1.2.2). Masters configure the SyncManagers from the ESI Sm elements or the SII SyncM category, and those "
        "that consult 0x1C00 read it from the device over SDO, never from these offline defaults; a default that "
        "disagrees with the Sm list is a stale copy (Beckhoff CU2508, a mailbox-only device, still lists SM2/SM3 as "
        "process-data SMs). Where the ESI and the firmware come from the same generator, it can also announce a "
        "firmware whose own 0x1C00 is wrong: swapped SM2/SM3 types in SSC-generated firmware kept devices out of OP "
        "(OpenEtherCATsociety/SOEM #401). A warning. Defaults are read from DefaultValue or DefaultData.",
    .bad_example =
        "<Sm ...>Outputs</Sm> (SM2) ... 0x1C00 <SubItem><Name>SubIndex 003</Name><Info><DefaultValue>4</DefaultValue>",
    .good_example =
        "<Sm ...>Outputs</Sm> (SM2) ... 0x1C00 <SubItem><Name>SubIndex 003</Name><Info><DefaultValue>3</DefaultValue>",
    .check = check_1c00,
};

}  // namespace

void add_sm(std::vector<Rule>& out) {
    out.insert(out.end(), {
        sm_direction_mismatch,
        sm_mailbox_mode,
        sm_control_byte_reserved,
        sm_mailbox_position,
        sm_overlap,
        sm_size_zero,
        sm_size_range,
        sm_default_size_pdo,
        sm_mailbox_size,
        sm_1c00_mismatch,
    });
}

}  // namespace esi::rules
