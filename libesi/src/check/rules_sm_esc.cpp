// Rules of the sm area about what the ESC has room for (ESC datasheet section II): where
// SyncManagers and the boot mailbox lie in its address space (0x0000-0x0FFF registers, process RAM
// from 0x1000 up to the RAM size, the whole space 16 bits wide: the SM start and length registers
// 0x0800+8n are 16 bits), and how many SM register blocks it has (at most 16: 0x0800-0x087F).
// fmmu-count, the same for FMMUs, is in rules_fmmu.cpp.
#include <string>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "check/esc_controller.hpp"
#include "check/sm_memory.hpp"
#include "check/sm_roles.hpp"
#include "esi/number.hpp"

namespace esi::rules {

namespace {

constexpr std::uint64_t address_space_end = 0x10000;

// Register windows that Beckhoff's devices lay process-data SMs over on purpose: the distributed-
// clock registers 0x0900-0x09FF (EL1252/EL2252 read latch times and write the SYNC start time and
// activation through an SM: Beckhoff EL1xxx/EL2xxx catalogues, SMs at #x0910, #x0981, #x0990,
// #x09AE) and the digital I/O and general-purpose registers 0x0F00-0x0FFF (EL2xxx, EK18xx: 1-byte
// output SMs at #x0F00, #x0F01). Everything else below 0x1000 is the ESC's own control registers.
struct Window {
    std::uint64_t begin;
    std::uint64_t end;  // exclusive
};
constexpr Window data_register_windows[] = {{0x0900, 0x0A00}, {0x0F00, 0x1000}};

bool inside_data_registers(std::uint64_t begin, std::uint64_t end) {
    for (const Window& w : data_register_windows)
        if (begin >= w.begin && end <= w.end) return true;
    return false;
}

std::string hex4(std::uint64_t value) { return format_hex(value, 4); }

// The end of process RAM: 0x1000 + Info/EtherCATController/DpramSize (bytes) where the description
// gives it, else the end of the 16-bit address space, the most any ESC has.
std::uint64_t ram_end(const Device& device, std::string& because) {
    const XmlElement* dpram = device.extras.find("Info/EtherCATController/DpramSize");
    if (dpram) {
        const ParsedNumber n = parse_number(dpram->text);
        if (n.ok() && !n.value.negative && n.value.magnitude > 0 && n.value.magnitude <= address_space_end - process_memory_start) {
            because = "Info/EtherCATController/DpramSize " + std::to_string(n.value.magnitude) + " gives RAM up to " +
                      hex4(process_memory_start + n.value.magnitude - 1);
            return process_memory_start + n.value.magnitude;
        }
    }
    because = "the ESC address space ends at 0xFFFF";
    return address_space_end;
}

std::string sm_label(const SyncManager& sm, std::size_t number) {
    std::string label = "SM" + std::to_string(number);
    if (!sm.type.empty()) label += " '" + sm.type + "'";
    return label;
}

bool is_mailbox(SmRole role) { return role == SmRole::mailbox_out || role == SmRole::mailbox_in; }

void check_sms(const Device& device, std::uint64_t end_of_ram, const std::string& because, RuleContext& context) {
    for (std::size_t n = 0; n < device.sms.size(); ++n) {
        const SyncManager& sm = device.sms[n];
        if (!sm.start_address || sm.is_virtual.value_or(false)) continue;
        const std::uint64_t start = *sm.start_address;
        const std::uint64_t size = effective_size(device, n);
        const SmRole role = device_sm_role(device, sm);
        const std::uint64_t buffers = occupies_three_buffers(device, sm, size) ? 3 : 1;
        const std::uint64_t end = start + size * buffers;
        const auto range = [&] { return hex4(start) + (end - start > 1 ? ".." + hex4(end - 1) : ""); };  // for a message
        if (start < process_memory_start && is_mailbox(role)) {
            context.report(sm.pos, sm_label(sm, n) + " is a mailbox at " + range() +
                                       ", inside the ESC's register area (below 0x1000); a mailbox lives in process "
                                       "RAM, and the master's mailbox writes would overwrite ESC registers");
        } else if (start < process_memory_start && size > 0 && !inside_data_registers(start, end)) {
            context.report(sm.pos, sm_label(sm, n) + " lies at " + range() +
                                       ", on the ESC's control registers (below 0x1000, outside the distributed-clock "
                                       "registers 0x0900-0x09FF and the digital I/O registers 0x0F00-0x0FFF); process "
                                       "data belongs in process RAM from 0x1000");
        } else if (start >= process_memory_start && end > end_of_ram) {
            context.report(sm.pos, sm_label(sm, n) + " occupies " + range() + (buffers == 3 ? " (3 buffers)" : "") +
                                       ", past the end of the ESC's process RAM (" + because + ")");
        }
    }
}

// Eeprom/BootStrap: boot mailbox out offset, out size, in offset, in size, 16-bit little-endian
// each (SII words 0x14-0x17, ETG.2010). A wrong length is eeprom-boot-strap's finding.
void check_boot_strap(const Device& device, std::uint64_t end_of_ram, const std::string& because, RuleContext& context) {
    if (!device.eeprom || !device.eeprom->boot_strap) return;
    const HexData& boot = *device.eeprom->boot_strap;
    const auto bytes = boot.bytes();
    if (!bytes || bytes->size() != 8) return;
    const auto word = [&](std::size_t i) { return std::uint64_t((*bytes)[2 * i]) | std::uint64_t((*bytes)[2 * i + 1]) << 8; };
    const char* names[] = {"out (master -> slave)", "in (slave -> master)"};
    for (std::size_t m = 0; m < 2; ++m) {
        const std::uint64_t start = word(2 * m);
        const std::uint64_t size = word(2 * m + 1);
        if (size == 0) continue;  // no boot mailbox in this direction
        const auto range = [&] { return hex4(start) + ".." + hex4(start + size - 1); };  // for a message
        if (start < process_memory_start)
            context.report(boot.pos, std::string("BootStrap: the boot mailbox ") + names[m] + " at " + range() +
                                         " lies inside the ESC's register area (below 0x1000); SII words 0x14-0x17 "
                                         "give the master the SM0/SM1 addresses for BOOT");
        else if (start + size > end_of_ram)
            context.report(boot.pos, std::string("BootStrap: the boot mailbox ") + names[m] + " at " + range() +
                                         " runs past the end of the ESC's process RAM (" + because + ")");
    }
}

void check_address_area(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        std::string because;
        const std::uint64_t end_of_ram = ram_end(*device, because);
        check_sms(*device, end_of_ram, because, context);
        check_boot_strap(*device, end_of_ram, because, context);
    }
}

constexpr Rule sm_address_area{
    .id = "sm-address-area",
    .default_severity = Severity::error,
    .summary = "A SyncManager or boot mailbox on the ESC's control registers or past its process RAM",
    .rationale =
        "The ESC address space holds the registers at 0x0000-0x0FFF and process RAM from 0x1000 up to the RAM size "
        "(ESC datasheet section II; 1 KiB to 60 KiB by ESC, and never past 0xFFFF: the SM start register 0x0800+8n "
        "is 16 bits). The master writes Sm@StartAddress into the SM registers and the boot mailbox offsets "
        "(Eeprom/BootStrap, SII words 0x14-0x17) into SM0/SM1 for BOOT as they are. A mailbox on registers, or a "
        "process-data SM over control registers such as the AL control (0x0120) or the SM registers themselves "
        "(0x0800), makes the ESC redirect the master's register accesses, and the device never leaves INIT; one "
        "past the RAM reads and writes nothing (AL status 0x0016 invalid mailbox configuration, 0x001D/0x001E invalid "
        "output/input configuration). Process-data SMs on the distributed-clock registers 0x0900-0x09FF and the "
        "digital I/O registers 0x0F00-0x0FFF are how Beckhoff's timestamp and digital terminals work (EL1252, "
        "EL2252, EL2xxx, EK18xx) and are not reported. The RAM ends at 0x1000 + Info/EtherCATController/DpramSize "
        "where the description gives it; a buffered SM counts its three buffers.",
    .bad_example = "<Sm StartAddress=\"#x0800\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>",
    .good_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>",
    .check = check_address_area,
};

// ---- sm-count ---------------------------------------------------------------------------------

void check_sm_count(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document))
        report_blocks_past_limit(*device, device->sms, "SmCount", "SyncManagers", "SM", context);
}

constexpr Rule sm_count{
    .id = "sm-count",
    .default_severity = Severity::error,
    .summary = "More Sm elements than the ESC has SyncManagers (EtherCATController/SmCount, at most 16)",
    .rationale =
        "The n-th Sm element is SyncManager n, and the master writes it to the register block 0x0800 + 8n (ETG.1000.4; "
        "ESC datasheet section II). An ESC has as many SyncManagers as its register 0x0005 says (4 to 16), stated in "
        "the ESI as Info/EtherCATController/SmCount, and the register map has room for 16 at most (0x0880 onwards is "
        "no SM). An SM beyond that is written nowhere, and the process data assigned to it are never exchanged (the "
        "device answers PRE-OP -> SAFE-OP with AL status 0x0017 invalid SM configuration, or the master refuses "
        "it). A vendor's own, lower limit is profile-sm-count's (limits.max_sms).",
    .bad_example = "<Info><EtherCATController><SmCount>4</SmCount></EtherCATController></Info> … five <Sm> elements",
    .good_example = "<Info><EtherCATController><SmCount>4</SmCount></EtherCATController></Info> … four <Sm> elements",
    .check = check_sm_count,
};

}  // namespace

void add_sm_esc(std::vector<Rule>& out) {
    out.insert(out.end(), {
        sm_address_area,
        sm_count,
    });
}

}  // namespace esi::rules
