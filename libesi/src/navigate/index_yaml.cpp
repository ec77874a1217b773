// The index of a YAML device source. Its tokens come from the positioned YAML tree (node start
// and end); its definitions from the derived model the device source front end builds, so that a
// hover shows what a generated ESI will hold: the type and size of an object written as a name,
// the SM a PDO is assigned to by derivation, the SMs derivation adds. A source with errors is
// not derived; its index then holds only what the tree tells (indices and names).

#include <string>

#include "esi/number.hpp"
#include "esi/yaml/source.hpp"
#include "esi/yaml/tree.hpp"
#include "navigate/index.hpp"

namespace esi::navigate {

namespace {

using yaml::Node;

Node child(Node map, std::string_view key) {
    if (!map.IsMap()) return {};
    for (auto it = map.begin(); it != map.end(); ++it)
        if (it->first.IsScalar() && it->first.Scalar() == key) return it->second;
    return {};
}

std::string scalar(Node node) { return node.IsScalar() ? node.Scalar() : std::string(); }

// A name as the source writes it: a text, or a map of languages whose first is shown.
std::string name_text(Node node) {
    if (node.IsScalar()) return node.Scalar();
    if (node.IsMap() && node.size() > 0) return scalar(node.begin()->second);
    return {};
}

// Decimal, or hex with `hex_digits` digits at least (0: decimal).
std::string number_text(const std::optional<std::uint32_t>& value, int hex_digits) {
    if (!value) return {};
    if (hex_digits == 0) return std::to_string(*value);
    std::string out = format_hex(*value, hex_digits);
    return out.replace(0, 2, "0x");
}

std::string value_text(const ObjectInfo* info) {
    if (!info) return {};
    if (info->default_value) return format_decimal(*info->default_value);
    if (info->default_string) return *info->default_string;
    if (info->default_data) return info->default_data->text;
    return {};
}

class YamlWalker {
public:
    explicit YamlWalker(Index& index) : index_(index), lines_(index.text) {}

    void walk(Node root, const EsiDocument* document) {
        const Node devices = child(root, "devices");
        const std::vector<Device>* model_devices =
            document && !document->infos.empty() ? &document->infos.front().devices : nullptr;
        std::size_t number = 0;
        if (devices.IsSequence())
            for (const Node device : devices) {
                const Device* model = model_devices && number < model_devices->size() ? &(*model_devices)[number] : nullptr;
                scope(device, model);
                ++number;
            }
        const Node modules = child(root, "modules");
        if (modules.IsSequence())
            for (const Node module : modules) scope(module, nullptr, true);
    }

private:
    // Byte offset of a tree position (1-based line, column in code points).
    std::size_t offset(SourcePos pos) const {
        if (!pos.known()) return 0;
        const auto start = lines_.offset_of(Position{pos.line - 1, 0});
        if (!start) return index_.text.size();
        std::size_t at = *start;
        for (std::uint32_t column = 1; column < pos.column && at < index_.text.size(); ++column) {
            ++at;
            while (at < index_.text.size() && (static_cast<unsigned char>(index_.text[at]) & 0xC0) == 0x80) ++at;
        }
        return at;
    }

    Span span(Node node) const {
        std::size_t begin = offset(node.pos());
        std::size_t end = std::max(begin, offset(node.end_pos()));
        // A quoted scalar's token is its text, without the quotes.
        if (node.IsScalar() && end - begin >= 2) {
            const char first = index_.text[begin];
            if ((first == '"' || first == '\'') && index_.text[end - 1] == first) {
                ++begin;
                --end;
            }
        }
        // A block node's end is where the next one starts: trim the blanks before it.
        while (end > begin && (index_.text[end - 1] == ' ' || index_.text[end - 1] == '\n' || index_.text[end - 1] == '\r'))
            --end;
        return Span{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)};
    }

    Span pair_span(Node key, Node value) const {
        return Span{span(key).begin, std::max(span(key).end, span(value).end)};
    }

    void add(Span where, Target target, bool declaration, std::uint32_t key = 0,
             std::optional<std::uint32_t> sub = std::nullopt) {
        index_.occurrences.push_back(Occurrence{where, target, declaration, scope_number_, key, sub});
    }

    Scope& current() { return index_.scopes[scope_number_]; }

    void scope(Node node, const Device* model, bool module = false) {
        if (!node.IsMap()) return;
        scope_number_ = static_cast<std::uint32_t>(index_.scopes.size());
        Scope& scope = index_.scopes.emplace_back();
        scope.module = module;
        const Node type = child(node, "type");
        scope.type = scalar(type);
        scope.name = name_text(child(node, "name"));
        scope.element = span(node);
        scope.decl = type.IsDefined() ? span(type) : Span{scope.element.begin, scope.element.begin};
        if (model) fill_from_model(*model);
        read_objects(child(node, "objects"));
        read_data_types(child(node, "data_types"));
        read_sms(child(node, "sms"));
        read_pdos(child(node, "rxpdo"), false);
        read_pdos(child(node, "txpdo"), true);
        read_init(child(node, "init"));
        if (const Node mailbox = child(node, "mailbox"); mailbox.IsMap()) read_init(child(child(mailbox, "coe"), "init"));
    }

    void fill_from_model(const Device& device) {
        Scope& scope = current();
        if (const Dictionary* dictionary = device.dictionary()) {
            for (const DataType& type : dictionary->data_types) {
                DataTypeDef def;
                def.name = type.name;
                def.base_type = type.base_type.value_or("");
                def.bit_size = std::to_string(type.bit_size);
                for (const DataTypeSubItem& item : type.sub_items) {
                    SubItemDef sub;
                    sub.subindex = item.subindex;
                    sub.name = item.name;
                    sub.type = item.type;
                    sub.bit_size = std::to_string(item.bit_size);
                    sub.bit_offset = std::to_string(item.bit_offset);
                    if (item.flags) {
                        sub.access = item.flags->access.value_or("");
                        sub.pdo_mapping = item.flags->pdo_mapping.value_or("");
                    }
                    def.sub_items.push_back(std::move(sub));
                }
                scope.data_types.push_back(std::move(def));
            }
            for (const Object& object : dictionary->objects) {
                ObjectDef def;
                def.index = object.index;
                def.name = primary_text(object.names);
                def.type = object.type;
                def.bit_size = std::to_string(object.bit_size);
                if (object.flags) {
                    def.access = object.flags->access.value_or("");
                    def.pdo_mapping = object.flags->pdo_mapping.value_or("");
                }
                if (object.info) {
                    def.default_value = value_text(&*object.info);
                    for (const auto& item : object.info->sub_items)
                        def.sub_defaults.emplace_back(item.name, value_text(&item.info));
                }
                scope.objects.push_back(std::move(def));
            }
        }
        for (const SyncManager& sm : device.sms) {
            SmDef def;
            def.number = static_cast<std::uint32_t>(scope.sms.size());
            def.role = sm.type;
            def.start_address = number_text(sm.start_address, 4);
            def.default_size = number_text(sm.default_size, 0);
            def.control_byte = number_text(sm.control_byte, 2);
            def.enable = number_text(sm.enable, 0);
            scope.sms.push_back(std::move(def));
        }
        for (const auto* pdos : {&device.rx_pdos, &device.tx_pdos})
            for (const Pdo& pdo : *pdos) {
                PdoDef def;
                def.tx = pdo.direction == PdoDirection::tx;
                def.index = pdo.index;
                def.name = primary_text(pdo.names);
                def.sm = pdo.sm;
                for (const PdoEntry& entry : pdo.entries)
                    def.entries.push_back(PdoEntryDef{entry.index, entry.effective_subindex(), entry.bit_len,
                                                      primary_text(entry.names), {}, {}});
                scope.pdos.push_back(std::move(def));
            }
    }

    void type_reference(Node type) {
        if (type.IsScalar() && !type.Scalar().empty()) add(span(type), Target::data_type, false);
    }

    void read_objects(Node objects) {
        if (!objects.IsMap()) return;
        for (auto it = objects.begin(); it != objects.end(); ++it) {
            const Node key = it->first;
            const Node value = it->second;
            const auto index = parse_index_number(scalar(key));
            if (!index) continue;
            ObjectDef* def = nullptr;
            for (auto& object : current().objects)
                if (object.index == *index) def = &object;
            if (!def) {
                def = &current().objects.emplace_back();
                def->index = *index;
                def->name = name_text(child(value, "name"));
                def->type = scalar(child(value, "type"));
            }
            def->decl = span(key);
            def->element = pair_span(key, value);
            add(def->decl, Target::object, true, *index);
            type_reference(child(value, "type"));
            if (const Node entries = child(value, "entries"); entries.IsMap())
                for (auto entry = entries.begin(); entry != entries.end(); ++entry) {
                    if (const auto subindex = parse_index_number(scalar(entry->first)))
                        def->sub_decls.emplace_back(*subindex, span(entry->first));
                    type_reference(child(entry->second, "type"));
                }
        }
    }

    void read_data_types(Node types) {
        auto one = [&](Node name_node, Node body) {
            const std::string name = scalar(name_node);
            DataTypeDef* def = nullptr;
            for (auto& type : current().data_types)
                if (type.name == name) def = &type;
            if (!def) {
                def = &current().data_types.emplace_back();
                def->name = name;
            }
            def->decl = span(name_node);
            def->element = pair_span(name_node, body);
            add(def->decl, Target::data_type, true);
            type_reference(child(body, "base_type"));
            if (const Node items = child(body, "sub_items"); items.IsSequence())
                for (const Node item : items) {
                    type_reference(child(item, "type"));
                    const Node item_name = child(item, "name");
                    const auto subindex = parse_index_number(scalar(child(item, "subindex")));
                    for (auto& sub : def->sub_items)
                        if (item_name.IsScalar() && sub.name == item_name.Scalar() && (!subindex || sub.subindex == subindex))
                            sub.decl = span(item_name);
                }
        };
        if (types.IsSequence()) {
            for (const Node type : types)
                if (const Node name = child(type, "name"); name.IsScalar()) one(name, type);
        } else if (types.IsMap()) {
            for (auto it = types.begin(); it != types.end(); ++it) one(it->first, it->second);
        }
    }

    void read_sms(Node sms) {
        if (!sms.IsSequence()) return;
        std::uint32_t number = 0;
        for (const Node sm : sms) {
            if (number >= current().sms.size()) {
                SmDef& def = current().sms.emplace_back();
                def.number = number;
                def.role = scalar(child(sm, "type"));
            }
            SmDef& def = current().sms[number];
            const Node type = child(sm, "type");
            def.decl = type.IsDefined() ? span(type) : span(sm);
            def.element = span(sm);
            add(def.decl, Target::sync_manager, true, number);
            ++number;
        }
    }

    void read_pdos(Node pdos, bool tx) {
        if (!pdos.IsSequence()) return;
        for (const Node item : pdos) {
            const Node index_node = child(item, "index");
            const auto index = parse_index_number(scalar(index_node));
            if (!index) continue;
            PdoDef* def = nullptr;
            for (auto& pdo : current().pdos)
                if (pdo.index == *index && pdo.tx == tx) def = &pdo;
            if (!def) {
                def = &current().pdos.emplace_back();
                def->tx = tx;
                def->index = *index;
                def->name = name_text(child(item, "name"));
            }
            def->decl = span(index_node);
            def->element = span(item);
            add(def->decl, Target::pdo, true, *index);
            if (const Node sm = child(item, "sm"); sm.IsScalar())
                if (const auto number = parse_index_number(sm.Scalar())) add(span(sm), Target::sync_manager, false, *number);
            const Node entries = child(item, "entries");
            if (!entries.IsSequence()) continue;
            // Entries are in mapping order in the source and in the derived PDO alike.
            std::size_t position = 0;
            for (const Node entry : entries) {
                const Node token = entry.IsMap() ? child(entry, "object") : entry;
                if (position < def->entries.size()) {
                    PdoEntryDef& derived = def->entries[position];
                    derived.decl = token.IsDefined() ? span(token) : span(entry);
                    derived.element = span(entry);
                    if (derived.index != 0 && token.IsScalar())
                        add(span(token), Target::object, false, derived.index, derived.subindex);
                } else if (token.IsScalar()) {
                    if (const auto reference = resolve(token.Scalar()))
                        add(span(token), Target::object, false, reference->first, reference->second);
                }
                ++position;
            }
        }
    }

    void read_init(Node commands) {
        if (!commands.IsSequence()) return;
        for (const Node command : commands) {
            const Node object = child(command, "object");
            if (!object.IsScalar()) continue;
            auto reference = resolve(object.Scalar());
            if (!reference) continue;
            if (const auto subindex = parse_index_number(scalar(child(command, "subindex")))) reference->second = *subindex;
            add(span(object), Target::object, false, reference->first, reference->second);
        }
    }

    // An object as a source names it: "0x6000", "0x6000:1" or the object's name.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> resolve(std::string_view text) const {
        if (auto reference = parse_reference(text)) return reference;
        for (const ObjectDef& object : index_.scopes[scope_number_].objects)
            if (object.name == text) return std::make_pair(object.index, std::uint32_t{0});
        return std::nullopt;
    }

    // "0x6000" or "0x6000:1".
    static std::optional<std::pair<std::uint32_t, std::uint32_t>> parse_reference(std::string_view text) {
        const std::size_t colon = text.find(':');
        const auto index = parse_index_number(text.substr(0, colon));
        if (!index) return std::nullopt;
        std::uint32_t subindex = 0;
        if (colon != std::string_view::npos) {
            const auto sub = parse_index_number(text.substr(colon + 1));
            if (!sub) return std::nullopt;
            subindex = *sub;
        }
        return std::make_pair(*index, subindex);
    }

    Index& index_;
    LineMap lines_;
    std::uint32_t scope_number_ = 0;
};

}  // namespace

void index_yaml(Index& index) {
    Diagnostics diagnostics;
    bool empty = false;
    const auto tree = yaml::Tree::parse(index.text, index.path, yaml::TreeLimits{}, diagnostics, empty);
    if (!tree || !tree->root()) return;
    const DeviceSource source = load_device_source(index.text, index.path);
    YamlWalker(index).walk(Node(tree->root()), source.document ? &*source.document : nullptr);
}

}  // namespace esi::navigate
