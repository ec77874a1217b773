// The CoE start-up commands of one slave (ENI Mailbox/CoE/InitCmds), in the order TwinCAT and
// EC-Engineer write them (corpus exports; ETG.1000.6 SDO download, Ccs 1):
//  1. the PDO assignment objects 0x1C10 + n of the process-data SMs are cleared (sub-index 0 = 0);
//  2. each configurable (not Fixed) PDO, TxPDOs first: an assigned one gets its mapping
//     downloaded, one left out is cleared — only when the device allows PDO configuration;
//  3. the assignment: one sub-index per PDO, then the count in sub-index 0;
//  4. the ESI's own InitCmds (device, then modules), then NETWORK.yaml's SDOs.
// With CoE complete access each object is one command on sub-index 0 whose data start with the
// count as 16 bits (CherryECAT's and Murrelektronik's exports); the clear step then remains
// only when mappings are downloaded. All of it only when the ESI sets CoE@PdoAssign.

#include <algorithm>
#include <fmt/format.h>
#include <functional>

#include "esi/data_types.hpp"
#include "esi/ethercat/al_state.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/model/typed_value.hpp"
#include "slave_context.hpp"

namespace esi::net {

namespace {

void push16(std::vector<std::uint8_t>& out, std::uint32_t v) {
    out.push_back(static_cast<std::uint8_t>(v));
    out.push_back(static_cast<std::uint8_t>(v >> 8));
}

void push32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    push16(out, v & 0xFFFF);
    push16(out, v >> 16);
}

CoeCommand command(std::string comment, std::uint32_t index, std::uint32_t subindex, std::vector<std::uint8_t> data, CoeOrigin origin,
                   bool complete_access = false) {
    CoeCommand c;
    c.transitions = {"PS"};
    c.comment = std::move(comment);
    c.index = static_cast<std::uint16_t>(index);
    c.subindex = static_cast<std::uint8_t>(subindex);
    c.data = std::move(data);
    c.origin = origin;
    c.complete_access = complete_access;
    return c;
}

std::uint32_t mapping_value(const ConfiguredEntry& e) { return (e.index << 16) | (e.subindex << 8) | (e.bit_len & 0xFF); }

void mapping_commands(const ConfiguredPdo& pdo, bool complete_access, std::vector<CoeCommand>& out) {
    const std::string object = fmt::format("0x{:04X}", pdo.index);
    if (complete_access) {
        std::vector<std::uint8_t> data;
        push16(data, static_cast<std::uint32_t>(pdo.entries.size()));
        for (const ConfiguredEntry& e : pdo.entries) push32(data, mapping_value(e));
        out.push_back(command("download pdo " + object + " entries", pdo.index, 0, std::move(data), CoeOrigin::mapping, true));
        return;
    }
    out.push_back(command("clear pdo " + object + " entries", pdo.index, 0, {0}, CoeOrigin::mapping));
    for (std::size_t k = 0; k < pdo.entries.size(); ++k) {
        std::vector<std::uint8_t> data;
        push32(data, mapping_value(pdo.entries[k]));
        out.push_back(command(fmt::format("download pdo {} entry {}", object, k + 1), pdo.index, static_cast<std::uint32_t>(k + 1),
                              std::move(data), CoeOrigin::mapping));
    }
    out.push_back(command("download pdo " + object + " entry count", pdo.index, 0, {static_cast<std::uint8_t>(pdo.entries.size())},
                          CoeOrigin::mapping));
}

// The value type of an SDO: NETWORK.yaml's `type`, else the dictionary entry's.
std::optional<ValueType> value_type_of(const SdoSpec& sdo, const ObjectEntry* entry, const Dictionary* dictionary, std::string& why) {
    ValueType t;
    if (sdo.type) {
        const TypeName parsed = parse_type_name(*sdo.type);
        t.name = *sdo.type;
        if (parsed.kind == TypeName::Kind::basic && parsed.basic) {
            t.basic = parsed.basic;
            t.bit_size = parsed.basic->bit_size;
        } else if (parsed.kind == TypeName::Kind::string) {
            t.basic = find_basic_type("STRING");
            t.bit_size = std::uint64_t{parsed.string_length} * 8;
        } else if (const BasicType* standard = find_basic_type(standard_type_name_for(*sdo.type))) {
            t.basic = standard;
            t.bit_size = standard->bit_size;
        }
        if (!t.basic) {
            why = "'" + *sdo.type + "' is not a basic data type (BOOL, SINT … ULINT, REAL, LREAL, STRING(n) …)";
            return std::nullopt;
        }
        return t;
    }
    if (!entry || !entry->basic) {
        why = "the object dictionary gives no type for it; add 'type:' or give 'data:'";
        return std::nullopt;
    }
    t.basic = entry->basic;
    t.bit_size = entry->bit_size;
    t.name = entry->type;
    if (dictionary)
        if (const DataType* dt = dictionary->find_data_type(entry->type); dt && !dt->enums.empty()) t.enumeration = dt;
    return t;
}

// The transitions at which an SDO can be sent: the state machine's, but those into and out of
// BOOT (whose mailbox carries FoE only).
bool coe_transition(std::string_view text) {
    const std::optional<ethercat::Transition> t = ethercat::parse_transition(text);
    return t && ethercat::is_state_machine_transition(*t) && t->from != ethercat::AlState::boot && t->to != ethercat::AlState::boot;
}

void network_sdos(SlaveContext& c, std::vector<CoeCommand>& out) {
    const bool any_dictionary = has_dictionary(c);
    const bool device_ca = c.slave.mailbox && c.slave.mailbox->complete_access;
    for (const SdoSpec& sdo : c.spec.sdos) {
        const std::string where = fmt::format("{}:{:02X}", hex_index(sdo.index), sdo.subindex);
        bool ok = true;
        for (const std::string& t : sdo.transitions) {
            if (!coe_transition(t)) {
                c.error(sdo.transition_pos, "net-transition", "an SDO cannot be sent at " + t + " (the mailbox runs from PREOP on)");
                ok = false;
            } else if (!c.limits.allowed_transitions.empty() &&
                       std::find(c.limits.allowed_transitions.begin(), c.limits.allowed_transitions.end(), t) == c.limits.allowed_transitions.end()) {
                c.error(sdo.transition_pos, "net-limit-transition", "the device accepts start-up commands only at its allowed transitions (limits), not " + t);
                ok = false;
            }
        }
        if (sdo.complete_access && !device_ca) {
            c.error(sdo.pos, "net-sdo-complete-access", c.device.type.text + " does not support CoE complete access (CoE@CompleteAccess)");
            ok = false;
        }
        const FoundObject found = find_object(c, sdo.index);
        const Dictionary* dictionary = found.dictionary;
        const Object* object = found.object;
        const ObjectLayout layout = object ? layout_of(dictionary, *object) : ObjectLayout{};
        const ObjectEntry* entry = object ? layout.entry(sdo.subindex) : nullptr;
        if (any_dictionary && !object) {
            const bool typed = sdo.type || sdo.data;
            Diagnostic& d = typed ? c.warning(sdo.pos, "net-sdo-object", where + " is not in the object dictionary of " + c.device.type.text)
                                  : c.error(sdo.pos, "net-sdo-object",
                                            where + " is not in the object dictionary of " + c.device.type.text + "; give 'type:' to write it anyway");
            (void)d;
            ok = ok && typed;
        } else if (object && !entry && !sdo.complete_access) {
            c.error(sdo.pos, "net-sdo-object", fmt::format("{} ({}) has no sub-index {:02X}", hex_index(sdo.index), primary_text(object->names), sdo.subindex));
            ok = false;
        }
        if (entry && entry->flags && entry->flags->access && *entry->flags->access == "ro") {
            c.error(sdo.pos, "net-sdo-read-only", where + " (" + entry->name + ") is read-only");
            ok = false;
        }
        std::vector<std::uint8_t> data;
        if (sdo.data) {
            data = *sdo.data;
        } else if (sdo.value) {
            std::string why;
            const std::optional<ValueType> type = value_type_of(sdo, entry, dictionary, why);
            if (!type) {
                c.error(sdo.pos, "net-sdo-type", where + ": " + why);
                ok = false;
            } else {
                EncodedValue encoded = encode_value(*sdo.value, *type);
                if (!encoded.ok()) {
                    c.error(sdo.value->pos.known() ? sdo.value->pos : sdo.pos, "net-sdo-value", where + ": " + encoded.error);
                    ok = false;
                }
                data = std::move(encoded.bytes);
            }
        }
        if (c.limits.max_init_cmd_bytes && data.size() > *c.limits.max_init_cmd_bytes) {
            c.error(sdo.pos, "net-limit-sdo-size",
                    fmt::format("{}: {} bytes; the device transfers at most {} per start-up SDO (limits)", where, data.size(), *c.limits.max_init_cmd_bytes));
            ok = false;
        }
        if (!ok) continue;
        CoeCommand cmd = command(sdo.comment.value_or(where), sdo.index, sdo.subindex, std::move(data), CoeOrigin::network, sdo.complete_access);
        cmd.transitions = sdo.transitions;
        out.push_back(std::move(cmd));
    }
}

void esi_init_cmds(const std::vector<InitCmd>& cmds, CoeOrigin origin, const MasterSpec& master,
                   const std::function<std::uint32_t(const InitCmd&)>& index_of, std::vector<CoeCommand>& out) {
    for (const InitCmd& ic : cmds) {
        if (!ic.index) continue;
        CoeCommand c;
        for (const Transition& t : ic.transitions) c.transitions.push_back(t.text);
        c.comment = ic.comment.value_or("");
        c.index = static_cast<std::uint16_t>(index_of(ic));
        c.subindex = static_cast<std::uint8_t>(ic.subindex.value_or(0));
        c.data = ic.data.bytes().value_or(std::vector<std::uint8_t>{});
        c.complete_access = ic.complete_access.value_or(false);
        c.origin = origin;
        // CiA 402 interpolation time period (0x60C2:01, per axis every 0x800): TwinCAT and
        // EC-Engineer both write the task cycle in ms there (corpus: 10 ms -> 0a, 1 ms -> 01)
        // where the ESI says otherwise.
        if (c.index >= 0x60C2 && c.index < 0xA000 && (c.index - 0x60C2) % 0x800 == 0 && c.subindex == 1 && c.data.size() == 1 &&
            master.cycle_time_us % 1000 == 0 && master.cycle_time_us / 1000 <= 0xFF)
            c.data[0] = static_cast<std::uint8_t>(master.cycle_time_us / 1000);
        out.push_back(std::move(c));
    }
}

}  // namespace

void build_coe_init_cmds(SlaveContext& c, const MasterSpec& master) {
    if (!c.slave.mailbox || !c.slave.mailbox->coe) {
        if (!c.spec.sdos.empty()) c.error(c.spec.sdos.front().pos, "net-sdo-no-coe", c.device.type.text + " has no CoE mailbox; it takes no SDOs");
        return;
    }
    const MailboxSetup& m = *c.slave.mailbox;
    std::vector<CoeCommand>& out = c.slave.coe_init_cmds;
    if (m.pdo_assign) {
        std::vector<const SmSetup*> pd_sms;
        for (const SmSetup& sm : c.slave.sms)
            if (sm.is_process_data()) pd_sms.push_back(&sm);
        // Configurable PDOs, TxPDOs first, in ESI order; module PDOs after the device's.
        std::vector<std::pair<const ConfiguredPdo*, std::uint32_t>> configurable;  // assigned PDO or the index to clear
        if (m.pdo_config) {
            for (const PdoDirection direction : {PdoDirection::tx, PdoDirection::rx}) {
                for (const Pdo& p : c.device.pdos(direction)) {
                    if (p.fixed.value_or(false)) continue;
                    const auto it = std::find_if(c.slave.pdos.begin(), c.slave.pdos.end(),
                                                 [&](const ConfiguredPdo& a) { return !a.module && a.index == p.index; });
                    configurable.emplace_back(it == c.slave.pdos.end() ? nullptr : &*it, p.index);
                }
                for (const ConfiguredPdo& a : c.slave.pdos)
                    if (a.module && !a.fixed && a.direction == direction) configurable.emplace_back(&a, a.index);
            }
        }
        const bool clear_first = !m.complete_access || !configurable.empty();
        if (clear_first)
            for (const SmSetup* sm : pd_sms)
                out.push_back(command(fmt::format("clear sm pdos (0x{:04X})", 0x1C10 + sm->number), 0x1C10 + sm->number, 0, {0},
                                      CoeOrigin::assignment));
        for (const auto& [pdo, index] : configurable) {
            if (pdo) mapping_commands(*pdo, m.complete_access, out);
            else out.push_back(command(fmt::format("clear pdo 0x{:04X} entries", index), index, 0, {0}, CoeOrigin::mapping));
        }
        for (const SmSetup* sm : pd_sms) {
            const std::uint32_t object = 0x1C10 + sm->number;
            if (m.complete_access) {
                std::vector<std::uint8_t> data;
                push16(data, static_cast<std::uint32_t>(sm->pdos.size()));
                for (std::size_t p : sm->pdos) push16(data, c.slave.pdos[p].index);
                out.push_back(command(fmt::format("download pdo 0x{:04X} index", object), object, 0, std::move(data), CoeOrigin::assignment, true));
                continue;
            }
            for (std::size_t k = 0; k < sm->pdos.size(); ++k) {
                std::vector<std::uint8_t> data;
                push16(data, c.slave.pdos[sm->pdos[k]].index);
                out.push_back(command(fmt::format("download pdo 0x{:04X}:{:02X} index", object, k + 1), object,
                                      static_cast<std::uint32_t>(k + 1), std::move(data), CoeOrigin::assignment));
            }
            if (!sm->pdos.empty())
                out.push_back(command(fmt::format("download pdo 0x{:04X} count", object), object, 0,
                                      {static_cast<std::uint8_t>(sm->pdos.size())}, CoeOrigin::assignment));
        }
    } else {
        for (const ConfiguredPdo& p : c.slave.pdos)
            if (p.entries_configured)
                c.error(c.spec.pos, "net-pdo-config", c.device.type.text + " has no CoE PdoAssign; configured PDO entries cannot be downloaded");
    }
    if (c.device.mailbox->coe)
        esi_init_cmds(c.device.mailbox->coe->init_cmds, CoeOrigin::device, master, [](const InitCmd& ic) { return *ic.index; }, out);
    for (std::size_t i = 0; i < c.slave.modules.size(); ++i) {
        const Module& module = *c.slave.modules[i].module;
        if (!module.mailbox || !module.mailbox->coe) continue;
        esi_init_cmds(module.mailbox->coe->init_cmds, CoeOrigin::module, master,
                      [&](const InitCmd& ic) { return slot_index(c, i, *ic.index, ic.index_depend_on_slot.value_or(false)); }, out);
    }
    network_sdos(c, out);
}

}  // namespace esi::net
