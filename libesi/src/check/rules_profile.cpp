// Rules of the profile area: the limits a device family's manual states, as the .esi-lint.yaml
// that applies to the file declares them (limits:, or overrides with product_codes; samples for
// some device families in samples/profiles/). Each rule checks one Limits field and is silent
// unless that field is set.
#include <algorithm>
#include <string>

#include "check/areas.hpp"
#include "check/od_text.hpp"
#include "check/queries.hpp"

namespace esi::rules {

namespace {

template <class F>
void for_each_device(const EsiDocument& document, RuleContext& context, F&& f) {
    for (const auto& info : document.infos)
        for (const auto& device : info.devices) f(device, context.limits_for(device));
}

std::string ranges_text(const std::vector<IndexRange>& ranges) {
    std::string out;
    for (const auto& r : ranges) {
        if (!out.empty()) out += ", ";
        out += r.first == r.last ? object_address(r.first) : object_address(r.first) + "-" + object_address(r.last);
    }
    return out;
}

std::string list_text(const std::vector<std::uint32_t>& values) {
    std::string out;
    for (const auto v : values) {
        if (!out.empty()) out += ", ";
        out += std::to_string(v);
    }
    return out;
}

std::string list_text(const std::vector<std::string>& values) {
    std::string out;
    for (const auto& v : values) {
        if (!out.empty()) out += ", ";
        out += v;
    }
    return out;
}

// Every InitCmd of the device's mailbox protocols, with the protocol's name.
template <class F>
void for_each_init_cmd(const Device& device, F&& f) {
    if (!device.mailbox) return;
    const Mailbox& m = *device.mailbox;
    if (m.coe)
        for (const auto& c : m.coe->init_cmds) f("CoE", c);
    if (m.soe)
        for (const auto& c : m.soe->init_cmds) f("SoE", c);
    if (m.eoe)
        for (const auto& c : m.eoe->init_cmds) f("EoE", c);
    if (m.aoe)
        for (const auto& c : m.aoe->init_cmds) f("AoE", c);
}

// ---- profile-max-pdos -----------------------------------------------------------------------

void check_max_pdos(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        for (const auto direction : {PdoDirection::rx, PdoDirection::tx}) {
            const std::optional<std::uint32_t>& max = direction == PdoDirection::rx ? limits.max_rx_pdos : limits.max_tx_pdos;
            const auto& pdos = device.pdos(direction);
            if (!max || pdos.size() <= *max) continue;
            const Pdo& first_excess = pdos[*max];
            context.report(first_excess.pos, "the device declares " + std::to_string(pdos.size()) + " " +
                                                 std::string(first_excess.element_name()) + "s; its profile allows at most " +
                                                 std::to_string(*max) + " (this is number " + std::to_string(*max + 1) + ")");
        }
    });
}

constexpr Rule profile_max_pdos{
    .id = "profile-max-pdos",
    .default_severity = Severity::error,
    .summary = "More PDOs in a direction than the device supports (limits.max_pdos)",
    .rationale =
        "Devices support a fixed number of PDOs: the item/Afag servo controllers 'unterstützt vier Receive-PDOs "
        "(RxPDO) und vier Transmit-PDOs (TxPDO)' (the item C series and Afag SE-Power EtherCAT manuals §6.1.1, "
        "Tabelle 5), the STÖBER inverters 'vier PDO-Kanäle' (STÖBER ECS 5000 EtherCAT manual §7.1). An ESI that "
        "declares more offers PDOs the firmware does not have. Set with `limits: { max_pdos: { rx: 4, tx: 4 } }`.",
    .bad_example = "limits: { max_pdos: { rx: 4 } } and five RxPdo elements",
    .good_example = "limits: { max_pdos: { rx: 4 } } and four RxPdo elements",
    .check = check_max_pdos,
};

// ---- profile-pdo-index-range ----------------------------------------------------------------

void check_pdo_index_range(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        for (const auto direction : {PdoDirection::rx, PdoDirection::tx}) {
            const auto& ranges = direction == PdoDirection::rx ? limits.rx_pdo_ranges : limits.tx_pdo_ranges;
            if (ranges.empty()) continue;
            for (const auto& pdo : device.pdos(direction)) {
                if (pdo.index_pos.line == 0 || pdo.index_invalid) continue;
                if (std::any_of(ranges.begin(), ranges.end(), [&](const IndexRange& r) { return r.contains(pdo.index); })) continue;
                context.report(pdo.index_pos, std::string(pdo.element_name()) + " index " + object_address(pdo.index) +
                                                  " is outside the profile's " + std::string(pdo.element_name()) + " indices " +
                                                  ranges_text(ranges));
            }
        }
    });
}

constexpr Rule profile_pdo_index_range{
    .id = "profile-pdo-index-range",
    .default_severity = Severity::error,
    .summary = "A PDO index outside the device's own index range (limits.pdo_index_ranges)",
    .rationale =
        "Beyond the general ETG ranges, a device implements only its own mapping objects: 0x1600-0x1603 and "
        "0x1A00-0x1A03 for the item/Afag servo controllers (the item C series and Afag SE-Power EtherCAT manuals "
        "§6.1.1, Tabelle 5, §6.1.2.5/6) and the STÖBER inverters (STÖBER ECS 5000 EtherCAT manual §10.1, "
        "A225-A228/A233-A236). A PDO at 0x1604 maps an object the device does not have. Set with `limits: { "
        "pdo_index_ranges: { rx: [\"0x1600-0x1603\"], tx: [\"0x1A00-0x1A03\"] } }`.",
    .bad_example = "pdo_index_ranges: { rx: [\"0x1600-0x1603\"] } and <RxPdo><Index>#x1604</Index>",
    .good_example = "pdo_index_ranges: { rx: [\"0x1600-0x1603\"] } and <RxPdo><Index>#x1603</Index>",
    .check = check_pdo_index_range,
};

// ---- profile-max-entries --------------------------------------------------------------------

void check_max_entries(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        if (!limits.max_entries_per_pdo) return;
        for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
            for (const auto& pdo : *list) {
                if (pdo.entries.size() <= *limits.max_entries_per_pdo) continue;
                context.report(pdo.pos, std::string(pdo.element_name()) + " " + object_address(pdo.index) + " has " +
                                            std::to_string(pdo.entries.size()) + " entries; the profile allows at most " +
                                            std::to_string(*limits.max_entries_per_pdo) + " per PDO");
            }
    });
}

constexpr Rule profile_max_entries{
    .id = "profile-max-entries",
    .default_severity = Severity::error,
    .summary = "A PDO with more entries than the device can map (limits.max_entries_per_pdo)",
    .rationale =
        "Mapping objects have a fixed number of sub-entries on many devices: the STÖBER inverters have 'einen "
        "Parameter mit sechs Subelementen' per PDO channel and direction (STÖBER ECS 5000 EtherCAT manual §7.1.1), so "
        "a seventh entry is rejected with SDO abort 0x06040042. Padding entries occupy a mapping entry too and are "
        "counted. Set with `limits: { max_entries_per_pdo: 6 }`.",
    .bad_example = "max_entries_per_pdo: 6 and an RxPdo with 7 entries",
    .good_example = "max_entries_per_pdo: 6 and an RxPdo with 6 entries",
    .check = check_max_entries,
};

// ---- profile-bitlen -------------------------------------------------------------------------

void check_bitlen(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        if (limits.allowed_bit_lens.empty()) return;
        for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
            for (const auto& pdo : *list)
                for (const auto& entry : pdo.entries) {
                    if (entry.is_padding() || entry.bit_len_pos.line == 0) continue;
                    const auto& allowed = limits.allowed_bit_lens;
                    if (std::find(allowed.begin(), allowed.end(), entry.bit_len) != allowed.end()) continue;
                    context.report(entry.bit_len_pos, entry_label(entry) + " has BitLen " + std::to_string(entry.bit_len) +
                                                          "; the profile allows only " + list_text(allowed));
                }
    });
}

constexpr Rule profile_bitlen{
    .id = "profile-bitlen",
    .default_severity = Severity::error,
    .summary = "An entry BitLen the device cannot map (limits.bitlen)",
    .rationale =
        "Some devices map only whole objects of certain widths: the item/Afag servo controllers accept BitLen 8, 16 "
        "or 32 (the item C series and Afag SE-Power EtherCAT manuals, Tabelle 14 and §6.7.2). Bit-sized entries are "
        "then rejected when the master downloads the mapping. Padding entries (Index 0) are exempt. Set with `limits: "
        "{ bitlen: [8, 16, 32] }`.",
    .bad_example = "bitlen: [8, 16, 32] and <Entry><Index>#x6040</Index><BitLen>1</BitLen>…",
    .good_example = "bitlen: [8, 16, 32] and <Entry><Index>#x6040</Index><BitLen>16</BitLen>…",
    .check = check_bitlen,
};

// ---- profile-fixed-sm -----------------------------------------------------------------------

void check_fixed_sm(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        for (const auto& [number, type] : limits.fixed_sms) {
            const std::string sm = "SM" + std::to_string(number);
            if (number >= device.sms.size()) {
                context.report(device.pos, "the profile fixes " + sm + " as " + type + ", but the device declares " +
                                               (device.sms.empty() ? std::string("no Sm") : "only SM0-SM" + std::to_string(device.sms.size() - 1)));
                continue;
            }
            const SyncManager& s = device.sms[number];
            const SmRole role = sm_role(s);
            if (to_string(role) == type) continue;
            context.report(s.pos, sm + " is " + (role == SmRole::unknown ? "of unknown type ('" + s.type + "')" : std::string(to_string(role))) +
                                      "; the profile fixes " + sm + " as " + type);
        }
    });
}

constexpr Rule profile_fixed_sm{
    .id = "profile-fixed-sm",
    .default_severity = Severity::error,
    .summary = "A SyncManager whose type differs from the device's fixed assignment (limits.fixed_sm)",
    .rationale =
        "Many devices hard-wire the use of their SyncManagers: SM0 mailbox out, SM1 mailbox in, SM2 outputs, SM3 "
        "inputs, 'fest und nicht durch den Anwender änderbar' on the item/Afag servo controllers (the item C series "
        "and Afag SE-Power EtherCAT manuals §6.1.1, §6.1.2.2: 0x1C00 = 1, 2, 3, 4) and the same roles on the STÖBER "
        "inverters (STÖBER ECS 5000 EtherCAT manual §8.2, §10.1). An ESI that declares them differently makes the "
        "device reject the SM configuration. Set with `limits: { fixed_sm: { 0: MBoxOut, 1: MBoxIn, 2: Outputs, 3: "
        "Inputs } }`.",
    .bad_example = "fixed_sm: { 2: Outputs } and <Sm …>Inputs</Sm> as the third Sm",
    .good_example = "fixed_sm: { 2: Outputs } and <Sm …>Outputs</Sm> as the third Sm",
    .check = check_fixed_sm,
};

// ---- profile-initcmd-transition -------------------------------------------------------------

void check_initcmd_transition(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        if (limits.allowed_transitions.empty()) return;
        const auto& allowed = limits.allowed_transitions;
        for_each_init_cmd(device, [&](std::string_view protocol, const InitCmd& cmd) {
            for (const auto& t : cmd.transitions) {
                if (std::find(allowed.begin(), allowed.end(), t.text) != allowed.end()) continue;
                context.report(t.pos.line ? t.pos : cmd.pos, std::string(protocol) + " InitCmd transition '" + t.text +
                                                                 "' is not one the profile allows (" + list_text(allowed) + ")");
            }
        });
    });
}

constexpr Rule profile_initcmd_transition{
    .id = "profile-initcmd-transition",
    .default_severity = Severity::error,
    .summary = "An InitCmd at a transition the device does not support (limits.transitions)",
    .rationale =
        "A device documents the state transitions it acts on: the item/Afag servo controllers list IP, PI, PS, SP, "
        "SO, OS, OP, SI and OI and implement no Bootstrap (the item C series and Afag SE-Power EtherCAT manuals, "
        "Tabelle 8, Tabelle 15, §6.2). An InitCmd at another transition is never executed or is refused. Set with "
        "`limits: { transitions: [IP, PS, SO] }`.",
    .bad_example = "transitions: [IP, PS, SO] and <InitCmd><Transition>IB</Transition>…",
    .good_example = "transitions: [IP, PS, SO] and <InitCmd><Transition>PS</Transition>…",
    .check = check_initcmd_transition,
};

// ---- profile-initcmd-size -------------------------------------------------------------------

void check_initcmd_size(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        if (!limits.max_init_cmd_bytes || !device.mailbox || !device.mailbox->coe) return;
        for (const auto& cmd : device.mailbox->coe->init_cmds) {
            if (!cmd.has_data || !cmd.data.valid() || cmd.data.byte_length() <= *limits.max_init_cmd_bytes) continue;
            const std::string target = cmd.index ? " for " + entry_address(*cmd.index, cmd.subindex.value_or(0)) : "";
            context.report(cmd.data.pos.line ? cmd.data.pos : cmd.pos,
                           "CoE InitCmd" + target + " writes " + std::to_string(cmd.data.byte_length()) +
                               " bytes; the profile allows at most " + std::to_string(*limits.max_init_cmd_bytes) + " bytes per SDO");
        }
    });
}

constexpr Rule profile_initcmd_size{
    .id = "profile-initcmd-size",
    .default_severity = Severity::error,
    .summary = "A CoE InitCmd writes more bytes than the device accepts per SDO (limits.max_init_cmd_bytes)",
    .rationale =
        "Some devices only support expedited SDO transfers: on the item/Afag servo controllers SDO access is limited "
        "to 32 bits because only standard CANopen objects of at most 4 bytes can be accessed, and segmented transfers "
        "carry 'max. 1 Segment mit 4 Byte Nutzdaten' (the item C series and Afag SE-Power EtherCAT manuals §6.3, "
        "Tabelle 15); the STÖBER inverters transfer every parameter as a 4-byte integer (STÖBER ECS 5000 EtherCAT "
        "manual §7.2). Longer InitCmd data is aborted at start-up. Set with `limits: { max_init_cmd_bytes: 4 }`.",
    .bad_example = "max_init_cmd_bytes: 4 and <InitCmd>…<Data>0000000000000000</Data></InitCmd>",
    .good_example = "max_init_cmd_bytes: 4 and <InitCmd>…<Data>00000000</Data></InitCmd>",
    .check = check_initcmd_size,
};

// ---- profile-mailbox-size -------------------------------------------------------------------

void check_mailbox_size(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        if (!limits.max_mailbox_size) return;
        for (std::size_t n = 0; n < device.sms.size(); ++n) {
            const SyncManager& sm = device.sms[n];
            const SmRole role = sm_role(sm);
            if (role != SmRole::mailbox_out && role != SmRole::mailbox_in) continue;
            const std::uint32_t size = std::max(sm.default_size.value_or(0), sm.max_size.value_or(0));
            if (size <= *limits.max_mailbox_size) continue;
            const bool from_max = sm.max_size.value_or(0) == size && sm.default_size.value_or(0) != size;
            context.report(sm.pos, "SM" + std::to_string(n) + " (" + std::string(to_string(role)) + ") has " +
                                       (from_max ? "MaxSize " : "DefaultSize ") + std::to_string(size) +
                                       "; the profile allows mailboxes of at most " + std::to_string(*limits.max_mailbox_size) + " bytes");
        }
    });
}

constexpr Rule profile_mailbox_size{
    .id = "profile-mailbox-size",
    .default_severity = Severity::error,
    .summary = "A mailbox SyncManager larger than the device supports (limits.max_mailbox_size)",
    .rationale =
        "The mailbox size is limited by the ESC and the firmware's buffers: the AX58100 takes at most 128 bytes per "
        "mailbox (kubabuda/EEPROM_generator 'Truncate MailboxSize to 128 when AX58100 ESC was selected'). A larger "
        "DefaultSize or MaxSize lets the master configure a mailbox the device overruns. Set with `limits: { "
        "max_mailbox_size: 128 }`.",
    .bad_example = "max_mailbox_size: 128 and <Sm DefaultSize=\"256\" …>MBoxOut</Sm>",
    .good_example = "max_mailbox_size: 128 and <Sm DefaultSize=\"128\" …>MBoxOut</Sm>",
    .check = check_mailbox_size,
};

// ---- profile-absent-object ------------------------------------------------------------------

void check_absent_object(const EsiDocument& document, RuleContext& context) {
    for_each_device(document, context, [&](const Device& device, const Limits& limits) {
        const auto& absent = limits.absent_objects;
        if (absent.empty()) return;
        const auto is_absent = [&](std::uint32_t index) { return std::find(absent.begin(), absent.end(), index) != absent.end(); };
        for (const auto& profile : device.profiles)
            if (profile.dictionary)
                for (const auto& object : profile.dictionary->objects)
                    if (object.index_pos.line && is_absent(object.index))
                        context.report(object.index_pos, "the Dictionary declares object " + object_address(object.index) +
                                                             ", which the profile says the device does not have");
        for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
            for (const auto& pdo : *list)
                for (const auto& entry : pdo.entries)
                    if (!entry.is_padding() && !entry.index_invalid && is_absent(entry.index))
                        context.report(entry.index_pos.line ? entry.index_pos : entry.pos,
                                       entry_label(entry) + " maps object " + object_address(entry.index) +
                                           ", which the profile says the device does not have");
        for_each_init_cmd(device, [&](std::string_view protocol, const InitCmd& cmd) {
            if (protocol == "CoE" && cmd.index && is_absent(*cmd.index))
                context.report(cmd.pos, "CoE InitCmd writes object " + object_address(*cmd.index) +
                                            ", which the profile says the device does not have");
        });
    });
}

constexpr Rule profile_absent_object{
    .id = "profile-absent-object",
    .default_severity = Severity::error,
    .summary =
        "An object the device does not have appears in the Dictionary, a PDO or an InitCmd (limits.absent_objects)",
    .rationale =
        "Manuals list objects a device lacks: the item/Afag servo controllers have no 0x1008, 0x1009 or 0x100A "
        "('Objekt ist nicht vorhanden', the item C series and Afag SE-Power EtherCAT manuals §6.1.2, Tabelle 6). An "
        "ESI that declares, maps or writes such an object promises what the device answers with SDO abort 0x06020000. "
        "Set with `limits: { absent_objects: [0x1008, 0x1009, 0x100A] }`.",
    .bad_example = "absent_objects: [0x1008] and <Object><Index>#x1008</Index>…",
    .good_example = "absent_objects: [0x1008] and no object #x1008",
    .check = check_absent_object,
};

}  // namespace

void add_profile(std::vector<Rule>& out) {
    out.insert(out.end(), {
        profile_max_pdos,
        profile_pdo_index_range,
        profile_max_entries,
        profile_bitlen,
        profile_fixed_sm,
        profile_initcmd_transition,
        profile_initcmd_size,
        profile_mailbox_size,
        profile_absent_object,
    });
}

}  // namespace esi::rules
