#include "esi/yaml/limits.hpp"

#include <algorithm>
#include <tuple>

namespace esi::yaml {

namespace {

std::optional<std::uint32_t> u32(Reader& r, const Node& node, std::string_view what) {
    return r.integer<std::uint32_t>(node, what);
}

std::vector<std::uint32_t> u32_list(Reader& r, const Node& node, std::string_view what) {
    std::vector<std::uint32_t> out;
    if (const auto items = r.sequence(node, what))
        for (const Node& item : *items)
            if (const auto v = u32(r, item, what)) out.push_back(*v);
    return out;
}

// "0x1600-0x1603" or "0x1600..0x1603".
std::optional<IndexRange> range_text(Reader& r, const Node& node, std::string_view what) {
    const std::string& s = node.Scalar();
    const std::size_t dots = s.find("..");
    const std::size_t cut = dots != std::string::npos ? dots : s.find('-', 1);
    const std::size_t skip = dots != std::string::npos ? 2 : 1;
    const ParsedNumber a = parse_number(std::string_view(s).substr(0, cut));
    const ParsedNumber b = parse_number(std::string_view(s).substr(cut + skip));
    if (a.ok() && b.ok() && !a.value.negative && !b.value.negative && a.value.magnitude <= 0xFFFFFFFFu &&
        b.value.magnitude <= 0xFFFFFFFFu)
        return IndexRange{static_cast<std::uint32_t>(a.value.magnitude), static_cast<std::uint32_t>(b.value.magnitude)};
    r.error(node, "yaml-type", "'" + std::string(what) + "': '" + s + "' is not a range such as \"0x1600-0x1603\"");
    return std::nullopt;
}

// A list of ranges: [first, last], "first-last", "first..last" or one index.
std::vector<IndexRange> ranges(Reader& r, const Node& node, std::string_view what) {
    std::vector<IndexRange> out;
    const auto items = r.sequence(node, what);
    if (!items) return out;
    for (const Node& item : *items) {
        std::optional<IndexRange> range;
        if (item.IsSequence() && item.size() == 2) {
            auto it = item.begin();
            const auto first = u32(r, *it, what);
            ++it;
            const auto last = u32(r, *it, what);
            if (first && last) range = IndexRange{*first, *last};
        } else if (item.IsScalar() && (item.Scalar().find("..") != std::string::npos || item.Scalar().find('-', 1) != std::string::npos)) {
            range = range_text(r, item, what);
        } else if (item.IsScalar()) {
            if (const auto v = u32(r, item, what)) range = IndexRange{*v, *v};
        } else {
            r.error(item, "yaml-type", "'" + std::string(what) + "': each range is [first, last] or \"first-last\"");
        }
        if (!range) continue;
        if (range->first > range->last) r.error(item, "yaml-type", "'" + std::string(what) + "': the range ends before it starts");
        else out.push_back(*range);
    }
    return out;
}

// "A-Z": the first and the last parameter group letter.
std::optional<std::pair<char, char>> group_letters(Reader& r, const Node& node) {
    const auto text = r.text(node, "parameter_index.groups");
    if (!text) return std::nullopt;
    const auto letter = [](char c) { return c >= 'A' && c <= 'Z'; };
    if (text->size() == 3 && letter((*text)[0]) && (*text)[1] == '-' && letter((*text)[2]) && (*text)[0] <= (*text)[2])
        return std::pair{(*text)[0], (*text)[2]};
    r.error(node, "yaml-type", "'parameter_index.groups': '" + *text + "' is not a range of upper-case group letters such as \"A-Z\"");
    return std::nullopt;
}

std::optional<ParameterIndexRule> parameter_index(Reader& r, const Node& node) {
    static constexpr std::string_view keys[] = {"base", "group_size", "groups"};
    const auto f = r.mapping(node, keys, "parameter_index");
    if (!f) return std::nullopt;
    const bool has_base = r.require(*f, "base", "parameter_index");
    const bool has_size = r.require(*f, "group_size", "parameter_index");
    ParameterIndexRule rule;
    const auto base = f->find("base") ? r.integer<std::uint32_t>(*f->find("base"), "parameter_index.base", 0, 0xFFFF) : std::nullopt;
    const auto size = f->find("group_size") ? r.integer<std::uint32_t>(*f->find("group_size"), "parameter_index.group_size", 1, 0x10000)
                                            : std::nullopt;
    if (const Node* n = f->find("groups")) {
        const auto letters = group_letters(r, *n);
        if (!letters) return std::nullopt;
        std::tie(rule.first_group, rule.last_group) = *letters;
    }
    if (!has_base || !has_size || !base || !size) return std::nullopt;
    rule.base = *base;
    rule.group_size = *size;
    if (rule.end() > 0x10000) {
        r.error(node, "yaml-value", "'parameter_index': the last group ends past index 0xFFFF");
        return std::nullopt;
    }
    return rule;
}

std::optional<Sync0CycleRule> sync0_cycle(Reader& r, const Node& node) {
    static constexpr std::string_view keys[] = {"min_ns", "multiple_of_ns", "factors"};
    const auto f = r.mapping(node, keys, "sync0_cycle");
    if (!f) return std::nullopt;
    Sync0CycleRule rule;
    if (const Node* n = f->find("min_ns")) rule.min_ns = r.integer<std::uint64_t>(*n, "sync0_cycle.min_ns");
    if (const Node* n = f->find("multiple_of_ns"))
        rule.multiple_of_ns = r.integer<std::uint64_t>(*n, "sync0_cycle.multiple_of_ns", 1);
    if (const Node* n = f->find("factors"))
        if (const auto items = r.sequence(*n, "sync0_cycle.factors"))
            for (const Node& item : *items)
                if (const auto v = r.integer<std::int32_t>(item, "sync0_cycle.factors")) rule.factors.push_back(*v);
    return rule;
}

}  // namespace

Limits read_limits(Reader& r, const Node& node) {
    Limits l;
    const auto f = r.mapping(node, Context::limits, "limits");
    if (!f) return l;
    static constexpr std::string_view directions[] = {"rx", "tx"};
    if (const Node* n = f->find("max_pdos")) {
        if (n->IsMap()) {
            if (const auto d = r.mapping(*n, directions, "max_pdos")) {
                if (const Node* rx = d->find("rx")) l.max_rx_pdos = u32(r, *rx, "max_pdos.rx");
                if (const Node* tx = d->find("tx")) l.max_tx_pdos = u32(r, *tx, "max_pdos.tx");
            }
        } else if (const auto v = u32(r, *n, "max_pdos")) {
            l.max_rx_pdos = l.max_tx_pdos = v;
        }
    }
    if (const Node* n = f->find("pdo_index_ranges")) {
        if (const auto d = r.mapping(*n, directions, "pdo_index_ranges")) {
            if (const Node* rx = d->find("rx")) l.rx_pdo_ranges = ranges(r, *rx, "pdo_index_ranges.rx");
            if (const Node* tx = d->find("tx")) l.tx_pdo_ranges = ranges(r, *tx, "pdo_index_ranges.tx");
        }
    }
    if (const Node* n = f->find("max_entries_per_pdo")) l.max_entries_per_pdo = u32(r, *n, "max_entries_per_pdo");
    if (const Node* n = f->find("bitlen")) l.allowed_bit_lens = u32_list(r, *n, "bitlen");
    if (const Node* n = f->find("fixed_sm")) {
        static constexpr std::string_view sm_types[] = {"MBoxOut", "MBoxIn", "Outputs", "Inputs"};
        if (!n->IsMap()) {
            r.error(*n, "yaml-type", "'fixed_sm' must map SM numbers to MBoxOut, MBoxIn, Outputs or Inputs");
        } else {
            const Fields fields(*n);
            for (const auto& item : fields.items()) {
                const auto sm = u32(r, item.key_node, "fixed_sm");
                const auto type = r.text(item.value, "fixed_sm");
                if (!type) continue;
                if (std::find(std::begin(sm_types), std::end(sm_types), *type) == std::end(sm_types)) {
                    r.error(item.value, "yaml-type",
                            "'fixed_sm': '" + *type + "' is not MBoxOut, MBoxIn, Outputs or Inputs" + did_you_mean(*type, sm_types));
                    continue;
                }
                if (sm) l.fixed_sms[*sm] = *type;
            }
        }
    }
    if (const Node* n = f->find("transitions")) {
        if (const auto items = r.sequence(*n, "transitions"))
            for (const Node& item : *items)
                if (const auto t = r.text(item, "transitions")) l.allowed_transitions.push_back(*t);
    }
    if (const Node* n = f->find("max_init_cmd_bytes")) l.max_init_cmd_bytes = u32(r, *n, "max_init_cmd_bytes");
    if (const Node* n = f->find("max_mailbox_size")) l.max_mailbox_size = u32(r, *n, "max_mailbox_size");
    if (const Node* n = f->find("absent_objects")) l.absent_objects = u32_list(r, *n, "absent_objects");
    if (const Node* n = f->find("mailbox_protocols")) {
        static constexpr std::string_view protocols[] = {"AoE", "EoE", "CoE", "FoE", "SoE", "VoE"};
        if (const auto items = r.sequence(*n, "mailbox_protocols"))
            for (const Node& item : *items) {
                const auto p = r.text(item, "mailbox_protocols");
                if (!p) continue;
                if (std::find(std::begin(protocols), std::end(protocols), *p) == std::end(protocols))
                    r.error(item, "yaml-type",
                            "'mailbox_protocols': '" + *p + "' is not AoE, EoE, CoE, FoE, SoE or VoE" + did_you_mean(*p, protocols));
                else
                    l.mailbox_protocols.push_back(*p);
            }
    }
    if (const Node* n = f->find("max_fmmus")) l.max_fmmus = u32(r, *n, "max_fmmus");
    if (const Node* n = f->find("max_sms")) l.max_sms = u32(r, *n, "max_sms");
    if (const Node* n = f->find("pdo_assign")) l.pdo_assign = r.boolean(*n, "pdo_assign");
    if (const Node* n = f->find("pdo_config")) l.pdo_config = r.boolean(*n, "pdo_config");
    if (const Node* n = f->find("pdo_names")) {
        if (const auto d = r.mapping(*n, directions, "pdo_names")) {
            if (const Node* rx = d->find("rx")) l.rx_pdo_name = r.text(*rx, "pdo_names.rx");
            if (const Node* tx = d->find("tx")) l.tx_pdo_name = r.text(*tx, "pdo_names.tx");
        }
    }
    if (const Node* n = f->find("parameter_index")) l.parameter_index = parameter_index(r, *n);
    if (const Node* n = f->find("sync0_cycle")) l.sync0_cycle = sync0_cycle(r, *n);
    return l;
}

}  // namespace esi::yaml
