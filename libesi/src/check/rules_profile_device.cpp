// Rules of the profile area about the device as a whole: its mailbox protocols, the ESC's FMMUs
// and SyncManagers, who configures the PDOs, the names its PDOs must carry, where its
// manufacturer parameters live and which SYNC0 cycles it takes. Like every profile-* rule, each
// checks one field of the limits that apply to the device (.esi-lint.yaml `limits:`, overrides
// by product code, or the YAML device source's own `limits:`) and is silent unless it is set.
#include <algorithm>
#include <cctype>
#include <string>

#include "check/areas.hpp"
#include "check/od_text.hpp"
#include "esi/ethercat/dc.hpp"

namespace esi::rules {

namespace {

template <class F>
void for_each_limited_device(const EsiDocument& document, RuleContext& context, F&& f) {
    for (const auto& info : document.infos)
        for (const auto& device : info.devices) f(device, context.limits_for(device));
}

std::string list_text(const std::vector<std::string>& values) {
    std::string out;
    for (const auto& v : values) out += (out.empty() ? "" : ", ") + v;
    return out;
}

SourcePos first_known(std::initializer_list<SourcePos> candidates) {
    for (const SourcePos& p : candidates)
        if (p.known()) return p;
    return {};
}

// ---- profile-mailbox-protocol ---------------------------------------------------------------

void check_mailbox_protocol(const EsiDocument& document, RuleContext& context) {
    for_each_limited_device(document, context, [&](const Device& device, const Limits& limits) {
        if (limits.mailbox_protocols.empty() || !device.mailbox) return;
        const Mailbox& m = *device.mailbox;
        // Each protocol element the Mailbox has, in ESI order; null where it has none.
        const std::pair<const char*, const SourcePos*> declared[] = {
            {"AoE", m.aoe ? &m.aoe->pos : nullptr}, {"EoE", m.eoe ? &m.eoe->pos : nullptr}, {"CoE", m.coe ? &m.coe->pos : nullptr},
            {"FoE", m.foe ? &m.foe->pos : nullptr}, {"SoE", m.soe ? &m.soe->pos : nullptr}, {"VoE", m.voe ? &m.voe->pos : nullptr},
        };
        const auto& allowed = limits.mailbox_protocols;
        for (const auto& [name, pos] : declared) {
            if (!pos || std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
            context.report(first_known({*pos, m.pos, device.pos}),
                           std::string("the Mailbox declares ") + name + "; the profile allows only " + list_text(allowed) +
                               ", and a master that uses " + name + " gets no answer or a mailbox error");
        }
    });
}

constexpr Rule profile_mailbox_protocol{
    .id = "profile-mailbox-protocol",
    .default_severity = Severity::error,
    .summary = "A mailbox protocol the device does not implement (limits.mailbox_protocols)",
    .rationale =
        "A device implements only some mailbox protocols: of CoE, SoE, FoE and EoE the item/Afag servo controllers "
        "support only CoE ('wird von der item C Serie unterstützt'), another protocol is error 62-2 'EtherCAT "
        "Protokollfehler kein CoE', and firmware goes over RS232, not FoE (the item C series and Afag SE-Power "
        "EtherCAT manuals §5, §6.5, Tabelle 19); the STÖBER inverters speak CoE for SDO and emergency and VoE for "
        "POSITool over EtherCAT (STÖBER ECS 5000 EtherCAT manual §7.2, §8, §12). An ESI that declares another protocol in its Mailbox "
        "makes the master use it (the SII mailbox protocol word follows the ESI, ETG.2010 word 0x1C). Set with "
        "`limits: { mailbox_protocols: [CoE] }`.",
    .bad_example = "mailbox_protocols: [CoE] and <Mailbox><CoE/><FoE/></Mailbox>",
    .good_example = "mailbox_protocols: [CoE] and <Mailbox><CoE/></Mailbox>",
    .check = check_mailbox_protocol,
};

// ---- profile-fmmu-count, profile-sm-count ---------------------------------------------------

template <class Element>
void check_count(RuleContext& context, const std::vector<Element>& elements, std::optional<std::uint32_t> max, const char* name,
                 const char* what) {
    if (!max || elements.size() <= *max) return;
    context.report(elements[*max].pos, std::string("the device declares ") + std::to_string(elements.size()) + " " + name +
                                           " elements; its ESC has " + std::to_string(*max) + " " + what +
                                           " (this is number " + std::to_string(*max + 1) + ")");
}

void check_fmmu_count(const EsiDocument& document, RuleContext& context) {
    for_each_limited_device(document, context, [&](const Device& device, const Limits& limits) {
        check_count(context, device.fmmus, limits.max_fmmus, "Fmmu", "FMMUs");
    });
}

constexpr Rule profile_fmmu_count{
    .id = "profile-fmmu-count",
    .default_severity = Severity::error,
    .summary = "More Fmmu elements than the device's ESC has FMMUs (limits.max_fmmus)",
    .rationale =
        "An ESC has a fixed number of FMMUs: the ESC20 FPGA of the item/Afag servo controllers has 4, the ESC10 2, "
        "ASICs 8 or more (the Afag SE-Power EtherCAT manual, Tabelle 4 'Vergleichsübersicht ESC10, ESC20 und ASIC'); "
        "the STÖBER ECS 5000 uses the ESC20 up to hardware version 7 (STÖBER ECS 5000 EtherCAT manual §9). The master "
        "configures one FMMU per Fmmu element (registers 0x0600 + 16 × n, ETG.1000.4); one the ESC does not have "
        "maps nothing and the process data stays invalid. Set with `limits: { max_fmmus: 4 }`.",
    .bad_example = "max_fmmus: 4 and five <Fmmu> elements",
    .good_example = "max_fmmus: 4 and <Fmmu>Outputs</Fmmu><Fmmu>Inputs</Fmmu><Fmmu>MBoxState</Fmmu>",
    .check = check_fmmu_count,
};

void check_sm_count(const EsiDocument& document, RuleContext& context) {
    for_each_limited_device(document, context, [&](const Device& device, const Limits& limits) {
        check_count(context, device.sms, limits.max_sms, "Sm", "SyncManagers");
    });
}

constexpr Rule profile_sm_count{
    .id = "profile-sm-count",
    .default_severity = Severity::error,
    .summary = "More Sm elements than the device's ESC has SyncManagers (limits.max_sms)",
    .rationale =
        "An ESC has a fixed number of SyncManagers: the ESC20 FPGA of the item/Afag servo controllers has 6, the "
        "ESC10 4, ASICs 8 or more (the Afag SE-Power EtherCAT manual, Tabelle 4 'Vergleichsübersicht ESC10, ESC20 und "
        "ASIC'); the STÖBER ECS 5000 uses the ESC20 up to hardware version 7 (STÖBER ECS 5000 EtherCAT manual §9). "
        "The master writes one SyncManager register block per Sm element (0x0800 + 8 × n, ETG.1000.4); one the ESC "
        "does not have is never active. Set with `limits: { max_sms: 6 }`.",
    .bad_example = "max_sms: 4 and five <Sm> elements",
    .good_example = "max_sms: 4 and <Sm>MBoxOut</Sm><Sm>MBoxIn</Sm><Sm>Outputs</Sm><Sm>Inputs</Sm>",
    .check = check_sm_count,
};

// ---- profile-pdo-assign, profile-pdo-config -------------------------------------------------

// The CoE flag and the InitCmd targets that make a master download what the device keeps.
struct PdoDownload {
    std::optional<bool> CoeProtocol::*flag;
    const char* flag_name;  // the CoE attribute
    const char* what;       // what the master would download
    bool (*writes)(std::uint32_t index);
};

// 0x1C10 + SM number (ETG.1000.6 SM assignment objects), 0x1600-0x17FF and 0x1A00-0x1BFF (mapping).
bool is_assignment_object(std::uint32_t index) { return index >= 0x1C10 && index <= 0x1C2F; }
bool is_mapping_object(std::uint32_t index) { return (index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF); }

constexpr PdoDownload assignment{&CoeProtocol::pdo_assign, "PdoAssign", "the PDO assignment", is_assignment_object};
constexpr PdoDownload mapping{&CoeProtocol::pdo_config, "PdoConfig", "the PDO mapping", is_mapping_object};

void check_download(const Device& device, std::optional<bool> allowed, const PdoDownload& d, RuleContext& context) {
    if (allowed.value_or(true) || !device.mailbox || !device.mailbox->coe) return;
    const CoeProtocol& coe = *device.mailbox->coe;
    if ((coe.*d.flag).value_or(false))
        context.report(first_known({coe.pos, device.mailbox->pos, device.pos}),
                       std::string("CoE ") + d.flag_name + " is set, so the master downloads " + d.what +
                           " at start-up; the profile says the device keeps its own and the master must not");
    for (const auto& cmd : coe.init_cmds)
        if (cmd.index && d.writes(*cmd.index))
            context.report(first_known({cmd.pos, coe.pos, device.pos}), "CoE InitCmd writes " + object_address(*cmd.index) +
                                                                            ", part of " + d.what +
                                                                            "; the profile says the master must not download it");
}

void check_pdo_assign(const EsiDocument& document, RuleContext& context) {
    for_each_limited_device(document, context, [&](const Device& device, const Limits& limits) {
        check_download(device, limits.pdo_assign, assignment, context);
    });
}

constexpr Rule profile_pdo_assign{
    .id = "profile-pdo-assign",
    .default_severity = Severity::error,
    .summary = "The ESI makes the master download a PDO assignment the device keeps itself (limits.pdo_assign)",
    .rationale =
        "Some devices take their PDO assignment from their own configuration: on the STÖBER inverters it is set in "
        "POSITool and held in A252/A253, and with the master's 'PDO-Zuordnung' switched off 'werden keine Änderungen "
        "per SDO vor dem Hochfahren des Umrichters vorgenommen' (STÖBER ECS 5000 EtherCAT manual §7.1.1, §10.1, "
        "§11.3 step 15). CoE@PdoAssign tells the master to write 0x1C12/0x1C13 at start-up (ETG.2000 CoE element), "
        "and an InitCmd writing 0x1C1x does the same. Set with `limits: { pdo_assign: false }`.",
    .bad_example = "pdo_assign: false and <CoE PdoAssign=\"true\"/>",
    .good_example = "pdo_assign: false and <CoE PdoAssign=\"false\"/>",
    .check = check_pdo_assign,
};

void check_pdo_config(const EsiDocument& document, RuleContext& context) {
    for_each_limited_device(document, context, [&](const Device& device, const Limits& limits) {
        check_download(device, limits.pdo_config, mapping, context);
    });
}

constexpr Rule profile_pdo_config{
    .id = "profile-pdo-config",
    .default_severity = Severity::error,
    .summary = "The ESI makes the master download a PDO mapping the device keeps itself (limits.pdo_config)",
    .rationale =
        "Some devices take their PDO mapping from their own configuration: the STÖBER inverters map their parameters "
        "in POSITool ('dieses wird empfohlen'), and the master's 'PDO-Konfiguration' must be switched off (STÖBER ECS "
        "5000 EtherCAT manual §7.1.1, §11.3 step 15); a mapping the master writes that differs from the inverter's "
        "makes it report 'PDO Länge ist nicht korrekt' (§8.2). CoE@PdoConfig tells the master to write 0x16xx/0x1Axx "
        "at start-up (ETG.2000 CoE element), and an InitCmd writing a mapping object does the same. Set with `limits: "
        "{ pdo_config: false }`.",
    .bad_example = "pdo_config: false and <CoE PdoConfig=\"true\"/>",
    .good_example = "pdo_config: false and <CoE PdoConfig=\"false\"/>",
    .check = check_pdo_config,
};

// ---- profile-pdo-name -----------------------------------------------------------------------

void check_pdo_name(const EsiDocument& document, RuleContext& context) {
    for_each_limited_device(document, context, [&](const Device& device, const Limits& limits) {
        for (const auto direction : {PdoDirection::rx, PdoDirection::tx}) {
            const std::optional<std::string>& required = direction == PdoDirection::rx ? limits.rx_pdo_name : limits.tx_pdo_name;
            if (!required) continue;
            for (const auto& pdo : device.pdos(direction)) {
                const std::string label = std::string(pdo.element_name()) + " " + object_address(pdo.index);
                if (pdo.names.empty())
                    context.report(pdo.pos, label + " has no Name; the profile requires '" + *required + "'");
                for (const auto& name : pdo.names)
                    if (name.text != *required)
                        context.report(first_known({name.pos, pdo.pos}),
                                       label + " is named '" + name.text + "'; the profile requires '" + *required + "'");
            }
        }
    });
}

constexpr Rule profile_pdo_name{
    .id = "profile-pdo-name",
    .default_severity = Severity::error,
    .summary = "A PDO not named as the device's manual requires (limits.pdo_names)",
    .rationale =
        "Some manuals fix the PDO names: on the item/Afag servo controllers the Name of an RxPdo 'muss … immer auf "
        "„Output“ gesetzt sein' (the example writes Outputs) and a TxPdo's is Inputs; the Name is not adjustable "
        "(the item C series and Afag SE-Power EtherCAT manuals §6.7.2 Tabelle 13, §6.7.3). Every Name element of "
        "the PDO is compared. Set with `limits: { pdo_names: { rx: Outputs, tx: Inputs } }`.",
    .bad_example = "pdo_names: { rx: Outputs } and <RxPdo><Index>#x1600</Index><Name>Controlword</Name>…",
    .good_example = "pdo_names: { rx: Outputs } and <RxPdo><Index>#x1600</Index><Name>Outputs</Name>…",
    .check = check_pdo_name,
};

// ---- profile-parameter-index ----------------------------------------------------------------

// CiA 301's manufacturer-specific area, where parameter groups live.
constexpr std::uint32_t manufacturer_first = 0x2000;
constexpr std::uint32_t manufacturer_last = 0x5FFF;

struct Coordinate {
    char group = 0;
    std::uint32_t line = 0;
    std::string text;  // "A180"
};

// A name that starts with a parameter coordinate: a group letter, the line number, then the end,
// a blank or '.' (an element, "A11.1").
std::optional<Coordinate> coordinate_of(const std::string& name) {
    if (name.size() < 2 || name[0] < 'A' || name[0] > 'Z') return std::nullopt;
    std::size_t end = 1;
    while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
    if (end == 1 || end - 1 > 6 || (end < name.size() && name[end] != ' ' && name[end] != '.')) return std::nullopt;
    return Coordinate{name[0], static_cast<std::uint32_t>(std::stoul(name.substr(1, end - 1))), name.substr(0, end)};
}

void check_parameter_index(const EsiDocument& document, RuleContext& context) {
    for_each_limited_device(document, context, [&](const Device& device, const Limits& limits) {
        if (!limits.parameter_index) return;
        const ParameterIndexRule& rule = *limits.parameter_index;
        const std::uint64_t groups_end = rule.end();
        for (const auto& profile : device.profiles) {
            if (!profile.dictionary) continue;
            for (const auto& object : profile.dictionary->objects) {
                if (object.index < manufacturer_first || object.index > manufacturer_last) continue;
                const SourcePos at = first_known({object.index_pos, object.pos});
                if (object.index >= groups_end && object.index >= rule.base) {
                    context.report(at, "object " + object_address(object.index) + " lies after the last parameter group (" +
                                           std::string(1, rule.last_group) + " ends at " +
                                           object_address(static_cast<std::uint32_t>(groups_end - 1)) +
                                           "); the rest of the manufacturer area up to #x5FFF is reserved");
                    continue;
                }
                const std::string& name = primary_text(object.names);
                const auto c = coordinate_of(name);
                if (!c) continue;
                const auto expected = rule.index_of(c->group, c->line);
                if (!expected) {
                    context.report(at, "object " + object_address(object.index) + " is named '" + name + "', but " + c->text +
                                           " is no parameter of the profile's groups " + rule.first_group + "-" +
                                           rule.last_group + " with lines 0-" + std::to_string(rule.group_size - 1));
                    continue;
                }
                if (*expected == object.index) continue;
                const unsigned group_number = static_cast<unsigned>(c->group - rule.first_group);
                context.report(at, "object " + object_address(object.index) + " is named '" + name + "', but parameter " +
                                       c->text + " is at " + object_address(*expected) + " = " + object_address(rule.base) +
                                       " + " + std::to_string(group_number) + " × " + object_address(rule.group_size) +
                                       " (group " + c->group + ") + " + std::to_string(c->line) + " (line)");
            }
        }
    });
}

constexpr Rule profile_parameter_index{
    .id = "profile-parameter-index",
    .default_severity = Severity::error,
    .summary = "A manufacturer parameter at another index than its group and line give (limits.parameter_index)",
    .rationale =
        "Some devices address their parameters by a group letter and a line number and place them by formula: on "
        "the STÖBER inverters 'die Zeilennummer nach der Gruppenangabe wird zum Startindex dazugezählt', group A "
        "starting at 0x2000 and each group 0x200 indices on (A154.2 is index 0x209A sub-index 2, C01 0x2401, E08 "
        "0x2808), groups A-Z up to 0x53FF and 0x5400-0x5FFF reserved (STÖBER ECS 5000 EtherCAT manual §7.2.4, "
        "§7.1.1). An object whose name starts with a coordinate ('A180 Device Control Byte') must sit at that index, "
        "or the master reads and maps another parameter. Objects in 0x2000-0x5FFF are checked; the mapping "
        "parameters A225-A236 live at 0x1600/0x1A00 and are not. Set with `limits: { parameter_index: { base: "
        "0x2000, group_size: 0x200, groups: A-Z } }`.",
    .bad_example = "parameter_index: { base: 0x2000, group_size: 0x200 } and <Object><Index>#x20B5</Index><Name>A180 "
                   "Device Control Byte</Name>…",
    .good_example = "parameter_index: { base: 0x2000, group_size: 0x200 } and <Object><Index>#x20B4</Index><Name>A180 "
                    "Device Control Byte</Name>…",
    .check = check_parameter_index,
};

// ---- profile-sync0-cycle --------------------------------------------------------------------

// AssignActivate bits 8 (cyclic operation) and 9 (SYNC0), ESC register 0x0981.
constexpr std::uint32_t activate_cyclic_sync0 = ethercat::assign_activate::sync0_cyclic;

std::string factors_text(const std::vector<std::int32_t>& factors) {
    std::string out;
    for (const auto f : factors) out += (out.empty() ? "" : ", ") + std::to_string(f);
    return out;
}

void check_sync0_cycle(const EsiDocument& document, RuleContext& context) {
    for_each_limited_device(document, context, [&](const Device& device, const Limits& limits) {
        if (!limits.sync0_cycle || !device.dc) return;
        const Sync0CycleRule& rule = *limits.sync0_cycle;
        for (const auto& mode : device.dc->op_modes) {
            if (!mode.has_assign_activate || (mode.assign_activate & activate_cyclic_sync0) != activate_cyclic_sync0 || !mode.cycle_time_sync0)
                continue;
            const DcTime& t = *mode.cycle_time_sync0;
            const SourcePos at = first_known({t.pos, mode.pos});
            const std::string label = "OpMode '" + mode.name + "'";
            if (t.value > 0) {
                const auto ns = static_cast<std::uint64_t>(t.value);
                if (rule.min_ns && ns < *rule.min_ns)
                    context.report(at, label + ": CycleTimeSync0 is " + std::to_string(ns) + " ns; the profile requires at least " +
                                           std::to_string(*rule.min_ns) + " ns");
                else if (rule.multiple_of_ns && ns % *rule.multiple_of_ns != 0)
                    context.report(at, label + ": CycleTimeSync0 is " + std::to_string(ns) + " ns; the profile requires a multiple of " +
                                           std::to_string(*rule.multiple_of_ns) + " ns");
                continue;
            }
            // 0 with a Factor: the SYNC0 cycle is the Sync unit cycle times the factor (divided by
            // it when negative), which the master chooses; only the factor is in the ESI.
            if (t.factor && !rule.factors.empty() && std::find(rule.factors.begin(), rule.factors.end(), *t.factor) == rule.factors.end())
                context.report(at, label + ": CycleTimeSync0 Factor is " + std::to_string(*t.factor) + "; the profile allows " +
                                       factors_text(rule.factors));
        }
    });
}

constexpr Rule profile_sync0_cycle{
    .id = "profile-sync0-cycle",
    .default_severity = Severity::error,
    .summary = "A SYNC0 cycle or cycle factor the device does not accept (limits.sync0_cycle)",
    .rationale =
        "Devices synchronise to SYNC0 only in some cycles: the STÖBER inverters need 'Zykluszeit ≥ 1000 µs' and 'ein "
        "ganzzahliges Vielfaches von 1000 µs' and otherwise stay in PRE-OP (STÖBER ECS 5000 EtherCAT manual §9, §10.1 "
        "A261, §11.5). Only what the ESI states can be checked: an explicit non-zero CycleTimeSync0 of an op mode "
        "that activates SYNC0 (min_ns, multiple_of_ns), and, where CycleTimeSync0 is 0 with a Factor (the SYNC0 cycle "
        "is the master's Sync unit cycle times the factor, or divided by it when negative; ETG.2000 OpMode), the "
        "factor (factors). The master's own cycle is not in the ESI and stays the master's to check. Set with "
        "`limits: { sync0_cycle: { min_ns: 1000000, multiple_of_ns: 1000000 } }`.",
    .bad_example = "sync0_cycle: { min_ns: 1000000 } and <OpMode>…<AssignActivate>#x0300</AssignActivate><CycleTimeSync0>"
                   "500000</CycleTimeSync0>…",
    .good_example = "sync0_cycle: { min_ns: 1000000 } and <OpMode>…<AssignActivate>#x0300</AssignActivate><CycleTimeSync0>"
                    "2000000</CycleTimeSync0>…",
    .check = check_sync0_cycle,
};

}  // namespace

void add_profile_device(std::vector<Rule>& out) {
    out.insert(out.end(), {
        profile_mailbox_protocol,
        profile_fmmu_count,
        profile_sm_count,
        profile_pdo_assign,
        profile_pdo_config,
        profile_pdo_name,
        profile_parameter_index,
        profile_sync0_cycle,
    });
}

}  // namespace esi::rules
