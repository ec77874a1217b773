// profile-… checks: a device family's own limits, as its manual states them and as the
// .esi-lint.yaml that applies to the file declares them (limits, or overrides by product code).
#include <algorithm>
#include <string>

#include "check/od_text.hpp"
#include "check/profile_checks.hpp"
#include "check/queries.hpp"

namespace esi::rules::profile {

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

}  // namespace

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

}  // namespace esi::rules::profile
