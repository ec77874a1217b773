// Which PDOs a slave assigns, to which SyncManager.
//
// Default (ETG.2000 PdoType): the PDOs whose Sm attribute is set, plus every Mandatory one;
// a TwinCAT AlternativeSmMapping marked Default="1" takes precedence, as TwinCAT applies it.
// NETWORK.yaml may give a mapping name or an explicit list instead; either must keep every
// Mandatory PDO, must not assign two PDOs that Exclude each other, and must equal the default
// when the device cannot change its assignment (no CoE PdoAssign).

#include <algorithm>
#include <fmt/format.h>
#include <set>

#include "esi/data_types.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/number.hpp"
#include "esi/yaml/reader.hpp"
#include "slave_context.hpp"
#include "sm_kind.hpp"

namespace esi::net {

namespace {

struct AlternativeMapping {
    std::string name;
    bool is_default = false;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> assignments;  // SM, PDO
};

std::vector<AlternativeMapping> alternative_mappings(const Device& device) {
    std::vector<AlternativeMapping> out;
    const XmlElement* twincat = device.extras.find("Info/VendorSpecific/TwinCAT");
    if (!twincat) return out;
    for (const XmlElement& e : twincat->children) {
        if (e.name != "AlternativeSmMapping") continue;
        AlternativeMapping m;
        if (const XmlElement* name = e.child("Name")) m.name = std::string(trim(name->text));
        if (const XmlAttribute* d = e.attribute("Default")) m.is_default = parse_boolean(d->value).value_or(false);
        for (const XmlElement& sm : e.children) {
            if (sm.name != "Sm") continue;
            const XmlAttribute* no = sm.attribute("No");
            const ParsedNumber n = no ? parse_number(no->value) : ParsedNumber{};
            if (!no || !n.ok()) continue;
            for (const XmlElement& pdo : sm.children) {
                const ParsedNumber p = parse_number(pdo.text);
                if (pdo.name == "Pdo" && p.ok())
                    m.assignments.emplace_back(static_cast<std::uint32_t>(n.value.magnitude), static_cast<std::uint32_t>(p.value.magnitude));
            }
        }
        out.push_back(std::move(m));
    }
    return out;
}

// The process-data SM a PDO goes to when nothing names one: the first of its direction.
std::optional<std::uint32_t> default_sm(const Device& device, PdoDirection direction) {
    const SmKind wanted = direction == PdoDirection::rx ? SmKind::outputs : SmKind::inputs;
    for (std::size_t i = 0; i < device.sms.size(); ++i)
        if (sm_kind_of(device.sms[i].type) == wanted) return static_cast<std::uint32_t>(i);
    return std::nullopt;
}

// An entry's type when the ESI leaves DataType out: the dictionary's, else one of its size.
std::string entry_type(const SlaveContext& c, std::uint32_t index, std::uint32_t subindex, std::uint32_t bit_len) {
    if (const FoundObject found = find_object(c, index); found.object)
        if (const ObjectEntry* e = layout_of(found.dictionary, *found.object).entry(subindex); e && !e->type.empty()) return e->type;
    switch (bit_len) {
        case 1: return "BOOL";
        case 8: return "USINT";
        case 16: return "UINT";
        case 32: return "UDINT";
        case 64: return "ULINT";
        default: return "BIT" + std::to_string(bit_len);
    }
}

ConfiguredPdo configured(const SlaveContext& c, const AvailablePdo& a, std::uint32_t sm) {
    ConfiguredPdo p;
    p.direction = a.pdo->direction;
    p.index = a.index;
    p.name = primary_text(a.pdo->names);
    p.sm = sm;
    p.fixed = a.pdo->fixed.value_or(false);
    p.mandatory = a.pdo->mandatory.value_or(false);
    p.index_depend_on_slot = a.pdo->index_depend_on_slot.value_or(false);
    p.module = a.module;
    // An Exclude that depends on the slot moves with the PDO's own index.
    for (const PdoExclude& e : a.pdo->excludes)
        p.excludes.push_back(e.index + (e.depend_on_slot.value_or(false) ? a.index - a.pdo->index : 0));
    for (const PdoEntry& e : a.pdo->entries) {
        ConfiguredEntry ce;
        const bool depend = e.index_depend_on_slot.value_or(false);
        ce.index = a.module ? slot_index(c, *a.module, e.index, depend) : e.index;
        ce.subindex = e.effective_subindex();
        ce.bit_len = e.bit_len;
        ce.name = primary_text(e.names);
        ce.comment = e.comment;
        ce.index_depend_on_slot = depend;
        if (!e.is_padding())
            ce.data_type = e.data_type && !e.data_type->empty() ? *e.data_type : entry_type(c, ce.index, ce.subindex, ce.bit_len);
        p.entries.push_back(std::move(ce));
    }
    return p;
}

std::string pdo_list(const std::vector<AvailablePdo>& available, PdoDirection direction) {
    std::string out;
    for (const AvailablePdo& a : available)
        if (a.pdo->direction == direction) out += (out.empty() ? "" : ", ") + hex_index(a.index);
    return out.empty() ? "none" : out;
}

struct Choice {
    const AvailablePdo* pdo = nullptr;
    std::uint32_t sm = 0;
    SourcePos pos;
};

}  // namespace

void select_pdos(SlaveContext& c) {
    const std::vector<AvailablePdo> available = available_pdos(c);
    auto find = [&](std::uint32_t index) -> const AvailablePdo* {
        for (const AvailablePdo& a : available)
            if (a.index == index) return &a;
        return nullptr;
    };
    const std::vector<AlternativeMapping> mappings = alternative_mappings(c.device);

    auto sm_for = [&](const AvailablePdo& a, SourcePos pos) -> std::optional<std::uint32_t> {
        std::optional<std::uint32_t> sm = a.pdo->sm ? a.pdo->sm : default_sm(c.device, a.pdo->direction);
        if (!sm) {
            c.error(pos, "net-pdo-sm",
                    fmt::format("{} {} has no Sm and {} has no {} SyncManager for it", a.pdo->element_name(), hex_index(a.index),
                                c.device.type.text, a.pdo->direction == PdoDirection::rx ? "Outputs" : "Inputs"));
            return std::nullopt;
        }
        const SmKind wanted = a.pdo->direction == PdoDirection::rx ? SmKind::outputs : SmKind::inputs;
        if (*sm >= c.device.sms.size() || sm_kind_of(c.device.sms[*sm].type) != wanted) {
            c.error(pos, "net-pdo-sm",
                    fmt::format("{} {} goes to SM{}, which is not an {} SyncManager of {}", a.pdo->element_name(), hex_index(a.index),
                                *sm, wanted == SmKind::outputs ? "Outputs" : "Inputs", c.device.type.text));
            return std::nullopt;
        }
        return sm;
    };

    // The default assignment.
    std::vector<Choice> defaults;
    const AlternativeMapping* default_mapping = nullptr;
    for (const AlternativeMapping& m : mappings)
        if (m.is_default && c.slave.modules.empty()) default_mapping = &m;
    if (default_mapping) {
        for (const auto& [sm, index] : default_mapping->assignments)
            if (const AvailablePdo* a = find(index)) defaults.push_back({a, sm, c.spec.pos});
    } else {
        for (const AvailablePdo& a : available)
            if (a.pdo->sm || a.pdo->mandatory.value_or(false))
                if (auto sm = sm_for(a, c.spec.pos)) defaults.push_back({&a, *sm, c.spec.pos});
    }

    std::vector<Choice> chosen;
    SourcePos selection_pos = c.spec.pos;
    if (c.spec.pdo_mapping) {
        selection_pos = c.spec.pdo_mapping_pos;
        const AlternativeMapping* mapping = nullptr;
        for (const AlternativeMapping& m : mappings)
            if (m.name == *c.spec.pdo_mapping) mapping = &m;
        if (!mapping) {
            std::vector<std::string_view> names;
            std::string list;
            for (const AlternativeMapping& m : mappings) {
                names.push_back(m.name);
                list += (list.empty() ? "'" : ", '") + m.name + "'";
            }
            c.error(c.spec.pdo_mapping_pos, "net-pdo-mapping",
                    mappings.empty() ? c.device.type.text + " has no named PDO mappings (AlternativeSmMapping)"
                                     : "no PDO mapping named '" + *c.spec.pdo_mapping + "'" + yaml::did_you_mean(*c.spec.pdo_mapping, names) +
                                           "; " + c.device.type.text + " has " + list);
            return;
        }
        for (const auto& [sm, index] : mapping->assignments) {
            if (const AvailablePdo* a = find(index)) chosen.push_back({a, sm, c.spec.pdo_mapping_pos});
            else c.error(c.spec.pdo_mapping_pos, "net-pdo-mapping", fmt::format("mapping '{}' names PDO {}, which {} does not have",
                                                                                 mapping->name, hex_index(index), c.device.type.text));
        }
    } else if (c.spec.pdos) {
        selection_pos = c.spec.pdos_pos;
        std::set<std::uint32_t> seen;
        for (const PdoRef& ref : *c.spec.pdos) {
            const AvailablePdo* a = find(ref.index);
            if (!a) {
                const bool rx = ref.index < 0x1A00;
                c.error(ref.pos, "net-pdo-unknown",
                        fmt::format("{} has no {} {}; its {}s: {}", c.device.type.text, rx ? "RxPDO" : "TxPDO", hex_index(ref.index),
                                    rx ? "RxPDO" : "TxPDO", pdo_list(available, rx ? PdoDirection::rx : PdoDirection::tx)));
                continue;
            }
            if (!seen.insert(ref.index).second) {
                c.error(ref.pos, "net-pdo-duplicate", hex_index(ref.index) + " is listed twice");
                continue;
            }
            if (auto sm = sm_for(*a, ref.pos)) chosen.push_back({a, *sm, ref.pos});
        }
    } else {
        chosen = defaults;
    }

    // Mandatory PDOs stay; PDOs that exclude each other do not go together.
    std::set<std::uint32_t> assigned;
    for (const Choice& ch : chosen) assigned.insert(ch.pdo->index);
    std::string missing;
    std::size_t missing_count = 0;
    for (const AvailablePdo& a : available)
        if (a.pdo->mandatory.value_or(false) && !assigned.count(a.index)) {
            missing += (missing.empty() ? "" : ", ") + hex_index(a.index);
            ++missing_count;
        }
    if (missing_count)
        c.error(selection_pos, "net-pdo-mandatory",
                fmt::format("{} {} Mandatory in the ESI and must be assigned", missing, missing_count == 1 ? "is" : "are"));
    std::set<std::pair<std::uint32_t, std::uint32_t>> reported;
    for (const Choice& ch : chosen) {
        const ConfiguredPdo p = configured(c, *ch.pdo, ch.sm);
        for (std::uint32_t excluded : p.excludes) {
            if (excluded == p.index || !assigned.count(excluded)) continue;
            if (!reported.insert(std::minmax(p.index, excluded)).second) continue;
            c.error(ch.pos, "net-pdo-exclude",
                    fmt::format("{} and {} exclude each other (ESI Exclude); assign one of them", hex_index(std::min(p.index, excluded)),
                                hex_index(std::max(p.index, excluded))));
        }
    }

    // A device without CoE PdoAssign keeps the assignment its ESI gives.
    const bool can_assign = c.coe() && c.device.mailbox->coe->pdo_assign.value_or(false);
    if (!can_assign && (c.spec.pdos || c.spec.pdo_mapping)) {
        std::set<std::pair<std::uint32_t, std::uint32_t>> want, have;
        for (const Choice& ch : defaults) want.insert({ch.sm, ch.pdo->index});
        for (const Choice& ch : chosen) have.insert({ch.sm, ch.pdo->index});
        if (want != have) {
            std::string list;
            for (const Choice& ch : defaults) list += (list.empty() ? "" : ", ") + hex_index(ch.pdo->index);
            c.error(selection_pos, "net-pdo-fixed-assignment",
                    fmt::format("{} cannot change its PDO assignment (no CoE PdoAssign in the ESI); it always assigns: {}",
                                c.device.type.text, list.empty() ? "nothing" : list));
        }
    }

    // The device family's limits.
    std::uint32_t rx_count = 0, tx_count = 0;
    for (const Choice& ch : chosen) {
        const bool rx = ch.pdo->pdo->direction == PdoDirection::rx;
        (rx ? rx_count : tx_count)++;
        const auto& ranges = rx ? c.limits.rx_pdo_ranges : c.limits.tx_pdo_ranges;
        if (!ranges.empty() && std::none_of(ranges.begin(), ranges.end(), [&](const IndexRange& r) { return r.contains(ch.pdo->index); }))
            c.error(ch.pos, "net-limit-pdo-range", fmt::format("{} is outside the device's PDO index ranges (limits)", hex_index(ch.pdo->index)));
        if (auto fixed = c.limits.fixed_sms.find(ch.sm); fixed != c.limits.fixed_sms.end() &&
                                                         fixed->second != (rx ? "Outputs" : "Inputs"))
            c.error(ch.pos, "net-limit-fixed-sm",
                    fmt::format("SM{} is fixed to {} on this device (limits); {} cannot go there", ch.sm, fixed->second, hex_index(ch.pdo->index)));
    }
    if (c.limits.max_rx_pdos && rx_count > *c.limits.max_rx_pdos)
        c.error(selection_pos, "net-limit-pdo-count", fmt::format("{} RxPDOs assigned; the device takes at most {} (limits)", rx_count, *c.limits.max_rx_pdos));
    if (c.limits.max_tx_pdos && tx_count > *c.limits.max_tx_pdos)
        c.error(selection_pos, "net-limit-pdo-count", fmt::format("{} TxPDOs assigned; the device takes at most {} (limits)", tx_count, *c.limits.max_tx_pdos));

    // Assigned PDOs in SM order, assignment order within an SM.
    std::stable_sort(chosen.begin(), chosen.end(), [](const Choice& a, const Choice& b) { return a.sm < b.sm; });
    for (const Choice& ch : chosen) c.slave.pdos.push_back(configured(c, *ch.pdo, ch.sm));
}

std::uint32_t ConfiguredPdo::bit_size() const {
    std::uint32_t bits = 0;
    for (const ConfiguredEntry& e : entries) bits += e.bit_len;
    return bits;
}

}  // namespace esi::net
