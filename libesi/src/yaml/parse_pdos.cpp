// PDOs and their entries (`rxpdo:`, `txpdo:`), shared by devices and modules. An entry names its
// object by index ("0x6041:1") or by name, or is padding ("pad8").

#include <algorithm>
#include <set>

#include "esi/derive/object_builder.hpp"
#include "esi/text_distance.hpp"
#include "yaml/extras.hpp"
#include "yaml/source_parser.hpp"

namespace esi::yaml {

namespace {

// "pad8", "pad 16": a padding entry of that many bits.
std::optional<std::uint32_t> padding_bits(std::string_view text) {
    if (text.size() < 4 || text.substr(0, 3) != "pad") return std::nullopt;
    const ParsedNumber n = parse_number(text.substr(3));
    if (!n.ok() || n.value.negative || n.value.magnitude == 0 || n.value.magnitude > 255) return std::nullopt;
    return static_cast<std::uint32_t>(n.value.magnitude);
}

}  // namespace

std::optional<PdoEntry> SourceParser::pdo_entry(const Node& node, const ObjectNames& names) {
    PdoEntry e;
    e.pos = pos_of(node);
    if (node.IsScalar()) {
        if (auto bits = padding_bits(node.Scalar())) {
            e.index = 0;
            e.bit_len = *bits;
            e.bit_len_pos = e.pos;
            return e;
        }
        auto ref = object_ref(node, names, "entry");
        if (!ref) return std::nullopt;
        if (ref->names_record) {
            r_.error(node, "yaml-reference",
                     "'" + node.Scalar() + "' is a record; name the entry as \"index:subindex\" or {object: …, subindex: …}");
            return std::nullopt;
        }
        e.index = ref->index;
        e.index_pos = e.pos;
        e.subindex = ref->subindex;
        if (e.index == 0) {
            r_.error(node, "yaml-value", "index 0 is padding; write padding as pad8, pad16 … or {pad: bits}");
            return std::nullopt;
        }
        return e;
    }
    const auto f = r_.mapping(node, Context::pdo_entry, "a PDO entry");
    if (!f) return std::nullopt;
    if (f->has("object") == f->has("pad")) {
        r_.error(f->node(), "yaml-missing-key", "a PDO entry needs either 'object' or 'pad'");
        return std::nullopt;
    }
    if (const Node* n = f->find("pad")) {
        e.index = 0;
        e.bit_len = r_.integer<std::uint32_t>(*n, "pad", 1, 255).value_or(0);
        e.bit_len_pos = pos_of(*n);
        if (f->has("bit_len")) r_.error(*f->key_node("bit_len"), "yaml-conflict", "'pad' is the padding's bit length; drop 'bit_len'");
        // Written files often spell padding <Index>0</Index><SubIndex>0</SubIndex>; keep that.
        r_.optional_integer<std::uint32_t>(*f, "subindex", e.subindex, 0, 255);
    } else {
        auto ref = object_ref(*f->find("object"), names, "object");
        if (!ref) return std::nullopt;
        e.index = ref->index;
        e.index_pos = pos_of(*f->find("object"));
        e.subindex = ref->subindex;
        if (const Node* n = f->find("subindex")) {
            const auto sub = r_.integer<std::uint32_t>(*n, "subindex", 0, 255);
            if (sub && ref->subindex && *ref->subindex != *sub)
                r_.error(*n, "yaml-conflict", "the sub-index is given twice ('object' and 'subindex') and differs");
            if (sub) e.subindex = sub;
        } else if (ref->names_record && !ref->subindex) {
            r_.error(*f->find("object"), "yaml-reference", "this object is a record; give 'subindex'");
            return std::nullopt;
        }
        if (e.index == 0) {
            r_.error(*f->find("object"), "yaml-value", "index 0 is padding; write {pad: bits}");
            return std::nullopt;
        }
        if (const Node* n = f->find("bit_len")) {
            e.bit_len = r_.integer<std::uint32_t>(*n, "bit_len", 1, 255).value_or(0);
            e.bit_len_pos = pos_of(*n);
        }
    }
    e.names = names_of(*f, "name");
    r_.optional_text(*f, "comment", e.comment);
    if (const Node* n = f->find("data_type")) {
        e.data_type = r_.text(*n, "data_type");
        e.data_type_pos = pos_of(*n);
    }
    r_.optional_text(*f, "dscale", e.data_type_dscale);
    if (const Node* n = f->find("swap_data")) {
        // ETG.2000: DataType@SwapData is one of Swap_HB_LB, Swap_HW_LW, Swap_HB_LB_HW_LW.
        static constexpr std::string_view swaps[] = {"Swap_HB_LB", "Swap_HW_LW", "Swap_HB_LB_HW_LW"};
        if (auto v = r_.text(*n, "swap_data")) {
            if (std::find(std::begin(swaps), std::end(swaps), *v) == std::end(swaps))
                r_.error(*n, "yaml-value",
                         "'swap_data' is Swap_HB_LB, Swap_HW_LW or Swap_HB_LB_HW_LW, not '" + *v + "'" + did_you_mean(*v, swaps));
            else
                e.data_type_swap_data = *v;
        }
    }
    r_.optional_bool(*f, "fixed", e.fixed);
    r_.optional_bool(*f, "index_depend_on_slot", e.index_depend_on_slot);
    r_.optional_bool(*f, "index_depend_on_slot_group", e.index_depend_on_slot_group);
    extras(*f, "xml", e.extras);
    return e;
}

std::vector<Pdo> SourceParser::pdos(const Node& node, PdoDirection direction, const ObjectNames& names, std::vector<bool>* assign) {
    std::vector<Pdo> out;
    const char* what = direction == PdoDirection::rx ? "rxpdo" : "txpdo";
    const auto items = r_.sequence(node, what);
    if (!items) return out;
    std::map<std::uint32_t, SourcePos> seen;
    for (const auto& item : *items) {
        const auto f = r_.mapping(item, Context::pdo, "a PDO");
        if (!f) continue;
        Pdo p;
        p.direction = direction;
        p.pos = f->pos();
        if (r_.require(*f, "index", "a PDO")) {
            p.index = r_.integer<std::uint32_t>(*f->find("index"), "index", 0, 0xFFFF).value_or(0);
            p.index_pos = pos_of(*f->find("index"));
            if (const auto [it, inserted] = seen.emplace(p.index, p.index_pos); !inserted) {
                Diagnostic& d = r_.error(p.index_pos, "yaml-duplicate", "PDO " + hex4(p.index) + " is declared twice");
                d.notes.push_back({r_.path(), it->second, "first declared here"});
            }
        }
        p.names = names_of(*f, "name");
        r_.optional_bool(*f, "fixed", p.fixed);
        r_.optional_bool(*f, "mandatory", p.mandatory);
        r_.optional_bool(*f, "virtual", p.is_virtual);
        r_.optional_integer<std::uint32_t>(*f, "sm", p.sm, 0, 31);
        bool assigned = true;
        if (const Node* n = f->find("assigned")) {
            assigned = r_.boolean(*n, "assigned").value_or(true);
            if (!assigned && f->has("sm")) r_.error(*n, "yaml-conflict", "'assigned: false' contradicts 'sm'");
        }
        if (assign) assign->push_back(assigned);
        r_.optional_integer<std::uint32_t>(*f, "su", p.su, 0, 255);
        if (const Node* n = f->find("exclude")) {
            if (auto list = r_.sequence(*n, "exclude")) {
                for (const auto& x : *list) {
                    PdoExclude ex;
                    ex.pos = pos_of(x);
                    if (x.IsMap()) {
                        const auto xf = r_.mapping(x, Context::pdo_exclude, "an exclude");
                        if (!xf || !r_.require(*xf, "index", "an exclude")) continue;
                        ex.index = r_.integer<std::uint32_t>(*xf->find("index"), "index", 0, 0xFFFF).value_or(0);
                        r_.optional_bool(*xf, "depend_on_slot", ex.depend_on_slot);
                        r_.optional_bool(*xf, "depend_on_slot_group", ex.depend_on_slot_group);
                    } else if (auto i = r_.integer<std::uint32_t>(x, "exclude", 0, 0xFFFF)) {
                        ex.index = *i;
                    } else {
                        continue;
                    }
                    p.excludes.push_back(ex);
                }
            }
        }
        if (const Node* n = f->find("excluded_sms")) {
            if (auto list = r_.sequence(*n, "excluded_sms"))
                for (const auto& x : *list)
                    if (auto v = r_.integer<std::uint32_t>(x, "excluded_sms", 0, 31)) p.excluded_sms.push_back(*v);
        }
        r_.optional_integer(*f, "pdo_order", p.pdo_order);
        r_.optional_integer(*f, "os_fac", p.os_fac);
        r_.optional_integer(*f, "os_min", p.os_min);
        r_.optional_integer(*f, "os_max", p.os_max);
        r_.optional_integer(*f, "os_index_inc", p.os_index_inc);
        r_.optional_bool(*f, "overwritten_by_module", p.overwritten_by_module);
        r_.optional_bool(*f, "sra_parameter", p.sra_parameter);
        r_.optional_text(*f, "safety_pdo_type", p.safety_pdo_type);
        r_.optional_integer(*f, "safety_conn_number", p.safety_conn_number);
        r_.optional_bool(*f, "index_depend_on_slot", p.index_depend_on_slot);
        r_.optional_bool(*f, "index_depend_on_slot_group", p.index_depend_on_slot_group);
        if (const Node* n = f->find("entries")) {
            if (auto list = r_.sequence(*n, "entries")) {
                if (list->size() > 254) r_.error(*n, "yaml-value", "a PDO maps at most 254 entries");
                for (const auto& x : *list)
                    if (auto e = pdo_entry(x, names)) p.entries.push_back(std::move(*e));
            }
        }
        extras(*f, "xml", p.extras);
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace esi::yaml
