// The index of an ESI file, from one pugixml parse of the editor's text. The ESI reader's model
// keeps a start position per element but not the range of each token, and it normalises what it
// reads; navigation needs the tokens as written, so this walk reads the parse tree directly and
// takes every range from pugixml's buffer offsets. A document that fails to parse (the editor
// is mid-edit) still yields the part parsed before the error.

#include <pugixml.hpp>

#include <cstring>
#include <vector>

#include "esi/number.hpp"
#include "navigate/index.hpp"
#include "navigate/xml_unescape.hpp"

namespace esi::navigate {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

class XmlWalker {
public:
    XmlWalker(Index& index, const char* buffer) : index_(index), text_(index.text), buffer_(buffer) {}

    // Devices and modules sit at a fixed depth (EtherCATInfo/Descriptions/Devices/Device, also
    // under an EtherCATInfoList; modules also in a module file's EtherCATModule/Modules); only those
    // containers are entered.
    void walk(pugi::xml_node node) {
        for (pugi::xml_node child : node.children()) {
            if (child.type() != pugi::node_element) continue;
            const std::string_view name = child.name();
            if (name == "Device" || name == "Module")
                scope(child, name == "Module");
            else if (name == "EtherCATInfoList" || name == "EtherCATInfo" || name == "EtherCATModule" ||
                     name == "Descriptions" || name == "Devices" || name == "Modules")
                walk(child);
        }
    }

private:
    // Offset of an element's '<'.
    std::size_t element_begin(pugi::xml_node node) const {
        const std::size_t name = static_cast<std::size_t>(node.name() - buffer_);
        return name > 0 ? name - 1 : 0;
    }

    // Offset after an element's end tag (or its "/>"); the end of the text when it is truncated.
    // Iterative: hostile input nests elements deeper than a stack allows, and pugixml parses it.
    std::size_t element_end(pugi::xml_node node) const {
        std::vector<pugi::xml_node> chain{node};
        while (const pugi::xml_node last = last_element_child(chain.back())) chain.push_back(last);
        const pugi::xml_node leaf = chain.back();
        std::size_t from = static_cast<std::size_t>(leaf.name() - buffer_) + std::strlen(leaf.name());
        if (!leaf.first_child()) {
            // No content: either <Name …/> or <Name …></Name>.
            char quote = 0;
            for (std::size_t i = from; i < text_.size(); ++i) {
                const char c = text_[i];
                if (quote) {
                    if (c == quote) quote = 0;
                } else if (c == '"' || c == '\'') {
                    quote = c;
                } else if (c == '>') {
                    from = i + 1;
                    if (text_[i - 1] == '/') chain.pop_back();  // closed already
                    break;
                }
            }
        }
        // Each end tag follows the end of the element's last child.
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) from = after_end_tag(*it, from);
        return from;
    }

    static pugi::xml_node last_element_child(pugi::xml_node node) {
        for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling())
            if (child.type() == pugi::node_element) return child;
        return {};
    }

    std::size_t after_end_tag(pugi::xml_node node, std::size_t from) const {
        if (from >= text_.size()) return text_.size();
        std::string closing = "</";
        closing += node.name();
        const std::size_t at = text_.find(closing, from);
        if (at == std::string_view::npos) return text_.size();
        const std::size_t gt = text_.find('>', at);
        return gt == std::string_view::npos ? text_.size() : gt + 1;
    }

    Span element_span(pugi::xml_node node) const {
        return Span{static_cast<std::uint32_t>(element_begin(node)), static_cast<std::uint32_t>(element_end(node))};
    }

    // The text of a simple element, trimmed, as written; an empty span after the start tag when
    // there is none.
    Span text_span(pugi::xml_node node) const {
        for (pugi::xml_node child : node.children()) {
            if (child.type() != pugi::node_pcdata && child.type() != pugi::node_cdata) continue;
            std::size_t begin = static_cast<std::size_t>(child.value() - buffer_);
            std::size_t end = text_.find(child.type() == pugi::node_cdata ? "]]>" : "<", begin);
            if (end == std::string_view::npos) end = text_.size();
            while (begin < end && is_blank(text_[begin])) ++begin;
            while (end > begin && is_blank(text_[end - 1])) --end;
            return Span{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)};
        }
        const std::size_t name_end = static_cast<std::size_t>(node.name() - buffer_) + std::strlen(node.name());
        const std::size_t gt = text_.find('>', name_end);
        const auto at = static_cast<std::uint32_t>(gt == std::string_view::npos ? text_.size() : gt + 1);
        return Span{at, at};
    }

    Span attribute_span(pugi::xml_attribute attribute) const {
        const auto begin = static_cast<std::size_t>(attribute.value() - buffer_);
        const char quote = begin > 0 ? text_[begin - 1] : '"';
        std::size_t end = text_.find(quote, begin);
        if (end == std::string_view::npos) end = text_.size();
        return Span{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)};
    }

    Span tag_name_span(pugi::xml_node node) const {
        const auto begin = static_cast<std::uint32_t>(node.name() - buffer_);
        return Span{begin, begin + static_cast<std::uint32_t>(std::strlen(node.name()))};
    }

    std::string text_of(pugi::xml_node node) const {
        if (!node) return {};
        const Span span = text_span(node);
        const std::string_view raw = index_.token(span);
        // CDATA is literal; text outside it may hold entities.
        if (span.begin >= 9 && index_.text.compare(span.begin - 9, 9, "<![CDATA[") == 0) return std::string(raw);
        return unescape_xml_text(raw);
    }

    // The first Name child (any LcId), as written.
    std::string name_of(pugi::xml_node node) const { return text_of(node.child("Name")); }

    void add(Span span, Target target, bool declaration, std::uint32_t key = 0,
             std::optional<std::uint32_t> sub = std::nullopt) {
        index_.occurrences.push_back(Occurrence{span, target, declaration, scope_number_, key, sub});
    }

    void scope(pugi::xml_node node, bool module) {
        scope_number_ = static_cast<std::uint32_t>(index_.scopes.size());
        Scope& scope = index_.scopes.emplace_back();
        scope.module = module;
        const pugi::xml_node type = node.child("Type");
        scope.type = text_of(type);
        scope.decl = type ? text_span(type) : tag_name_span(node);
        scope.name = name_of(node);
        scope.element = element_span(node);
        for (pugi::xml_node child : node.children()) {
            if (child.type() != pugi::node_element) continue;
            const std::string_view name = child.name();
            if (name == "Profile") {
                for (pugi::xml_node dictionary : child.children("Dictionary")) read_dictionary(dictionary);
            } else if (name == "Sm") {
                read_sm(child);
            } else if (name == "RxPdo" || name == "TxPdo") {
                read_pdo(child, name == "TxPdo");
            } else if (name == "Fmmu") {
                sm_reference(child.attribute("Sm"));
            } else if (name == "Dc") {
                read_dc(child);
            } else if (name == "Mailbox") {
                for (pugi::xml_node protocol : child.children())
                    for (pugi::xml_node command : protocol.children("InitCmd")) read_init_cmd(command);
            }
        }
    }

    Scope& current() { return index_.scopes[scope_number_]; }

    void sm_reference(pugi::xml_attribute attribute) {
        if (!attribute) return;
        const Span span = attribute_span(attribute);
        if (const auto number = parse_index_number(index_.token(span))) add(span, Target::sync_manager, false, *number);
    }

    void object_reference(pugi::xml_node index_element, pugi::xml_node subindex_element) {
        if (!index_element) return;
        const Span span = text_span(index_element);
        const auto index = parse_index_number(index_.token(span));
        if (!index) return;
        std::optional<std::uint32_t> sub = 0;
        if (subindex_element) sub = parse_index_number(text_of(subindex_element));
        add(span, Target::object, false, *index, sub);
    }

    void read_dictionary(pugi::xml_node dictionary) {
        for (pugi::xml_node type : dictionary.child("DataTypes").children("DataType")) read_data_type(type);
        for (pugi::xml_node object : dictionary.child("Objects").children("Object")) read_object(object);
    }

    void data_type_reference(pugi::xml_node element) {
        if (!element) return;
        const Span span = text_span(element);
        if (!span.empty()) add(span, Target::data_type, false);
    }

    void read_data_type(pugi::xml_node node) {
        DataTypeDef type;
        const pugi::xml_node name = node.child("Name");
        type.name = text_of(name);
        type.decl = name ? text_span(name) : tag_name_span(node);
        type.element = element_span(node);
        type.base_type = text_of(node.child("BaseType"));
        type.bit_size = text_of(node.child("BitSize"));
        if (const pugi::xml_node array = node.child("ArrayInfo")) {
            const auto lower = parse_number(text_of(array.child("LBound")));
            const auto elements = parse_number(text_of(array.child("Elements")));
            if (lower.ok() && elements.ok() && elements.value.magnitude > 0)
                type.array = "[" + format_decimal(lower.value) + ".." +
                             std::to_string(lower.value.magnitude + elements.value.magnitude - 1) + "]";
        }
        if (name) add(type.decl, Target::data_type, true);
        data_type_reference(node.child("BaseType"));
        for (pugi::xml_node item : node.children("SubItem")) {
            SubItemDef sub;
            if (const pugi::xml_node subindex = item.child("SubIdx")) sub.subindex = parse_index_number(text_of(subindex));
            const pugi::xml_node item_name = item.child("Name");
            sub.name = text_of(item_name);
            if (item_name) sub.decl = text_span(item_name);
            sub.type = text_of(item.child("Type"));
            sub.bit_size = text_of(item.child("BitSize"));
            sub.bit_offset = text_of(item.child("BitOffs"));
            sub.access = text_of(item.child("Flags").child("Access"));
            sub.pdo_mapping = text_of(item.child("Flags").child("PdoMapping"));
            data_type_reference(item.child("Type"));
            type.sub_items.push_back(std::move(sub));
        }
        current().data_types.push_back(std::move(type));
    }

    static std::string default_of(const XmlWalker& walker, pugi::xml_node info) {
        for (const char* element : {"DefaultValue", "DefaultString", "DefaultData"})
            if (const pugi::xml_node value = info.child(element)) return walker.text_of(value);
        return {};
    }

    void read_object(pugi::xml_node node) {
        const pugi::xml_node index_element = node.child("Index");
        if (!index_element) return;
        ObjectDef object;
        object.decl = text_span(index_element);
        const auto index = parse_index_number(index_.token(object.decl));
        if (!index) return;
        object.index = *index;
        object.element = element_span(node);
        object.name = name_of(node);
        object.type = text_of(node.child("Type"));
        object.bit_size = text_of(node.child("BitSize"));
        object.access = text_of(node.child("Flags").child("Access"));
        object.pdo_mapping = text_of(node.child("Flags").child("PdoMapping"));
        const pugi::xml_node info = node.child("Info");
        object.default_value = default_of(*this, info);
        for (pugi::xml_node item : info.children("SubItem")) {
            object.sub_defaults.emplace_back(name_of(item), default_of(*this, item.child("Info")));
            mapping_reference(object.index, item.child("Info").child("DefaultValue"));
        }
        add(object.decl, Target::object, true, object.index);
        data_type_reference(node.child("Type"));
        current().objects.push_back(std::move(object));
    }

    // The dictionary's own PDO mapping and assignment: a default of a mapping object (0x1600..,
    // 0x1A00..) is an entry "#x70000108" (index, subindex, bit length), one of an SM assignment
    // object (0x1C10..0x1C2F) a PDO index. Both are references like a PDO's Entry and Sm/Pdo.
    void mapping_reference(std::uint32_t object_index, pugi::xml_node value) {
        if (!value) return;
        const Span span = text_span(value);
        const auto number = parse_index_number(index_.token(span));
        if (!number) return;
        const bool mapping = (object_index >= 0x1600 && object_index <= 0x17FF) ||
                             (object_index >= 0x1A00 && object_index <= 0x1BFF);
        const bool assignment = object_index >= 0x1C10 && object_index <= 0x1C2F;
        if (mapping && (*number >> 16) != 0)
            add(span, Target::object, false, *number >> 16, (*number >> 8) & 0xFF);
        else if (assignment && *number >= 0x1600)  // sub-index 0 holds a count, not a PDO
            add(span, Target::pdo, false, *number);
    }

    void read_sm(pugi::xml_node node) {
        SmDef sm;
        sm.number = static_cast<std::uint32_t>(current().sms.size());
        sm.role = text_of(node);
        sm.decl = sm.role.empty() ? tag_name_span(node) : text_span(node);
        sm.element = element_span(node);
        sm.start_address = node.attribute("StartAddress").value();
        sm.default_size = node.attribute("DefaultSize").value();
        sm.control_byte = node.attribute("ControlByte").value();
        sm.enable = node.attribute("Enable").value();
        add(sm.decl, Target::sync_manager, true, sm.number);
        current().sms.push_back(std::move(sm));
    }

    void read_pdo(pugi::xml_node node, bool tx) {
        PdoDef pdo;
        pdo.tx = tx;
        const pugi::xml_node index_element = node.child("Index");
        pdo.decl = index_element ? text_span(index_element) : tag_name_span(node);
        const auto index = parse_index_number(index_.token(pdo.decl));
        pdo.index = index.value_or(0);
        pdo.element = element_span(node);
        pdo.name = name_of(node);
        if (const pugi::xml_attribute sm = node.attribute("Sm")) {
            pdo.sm = parse_index_number(sm.value());
            sm_reference(sm);
        }
        if (index) add(pdo.decl, Target::pdo, true, pdo.index);
        for (pugi::xml_node child : node.children()) {
            if (child.type() != pugi::node_element) continue;
            const std::string_view name = child.name();
            if (name == "Exclude") {
                const Span span = text_span(child);
                if (const auto excluded = parse_index_number(index_.token(span))) add(span, Target::pdo, false, *excluded);
            } else if (name == "Entry") {
                PdoEntryDef entry;
                const pugi::xml_node entry_index = child.child("Index");
                entry.decl = entry_index ? text_span(entry_index) : tag_name_span(child);
                entry.element = element_span(child);
                entry.index = parse_index_number(index_.token(entry.decl)).value_or(0);
                entry.subindex = parse_index_number(text_of(child.child("SubIndex"))).value_or(0);
                entry.bit_len = parse_index_number(text_of(child.child("BitLen"))).value_or(0);
                entry.name = name_of(child);
                if (entry.index != 0) object_reference(entry_index, child.child("SubIndex"));
                data_type_reference(child.child("DataType"));
                pdo.entries.push_back(std::move(entry));
            }
        }
        current().pdos.push_back(std::move(pdo));
    }

    void read_dc(pugi::xml_node dc) {
        for (pugi::xml_node mode : dc.children("OpMode"))
            for (pugi::xml_node sm : mode.children("Sm")) {
                sm_reference(sm.attribute("No"));
                for (pugi::xml_node pdo : sm.children("Pdo")) {
                    const Span span = text_span(pdo);
                    if (const auto index = parse_index_number(index_.token(span))) add(span, Target::pdo, false, *index);
                }
            }
    }

    void read_init_cmd(pugi::xml_node command) { object_reference(command.child("Index"), command.child("SubIndex")); }

    Index& index_;
    std::string_view text_;
    const char* buffer_;
    std::uint32_t scope_number_ = 0;
};

}  // namespace

void index_xml(Index& index) {
    pugi::xml_document document;
    // No entity expansion and no line-end conversion: the tree's values stay where the editor's
    // text has them, and the walk reads every token from that text, not from the tree.
    const unsigned options = pugi::parse_cdata;
    (void)document.load_buffer(index.text.data(), index.text.size(), options, pugi::encoding_utf8);
    const pugi::xml_node first = document.first_child();
    if (!first) return;
    // pugixml parses a copy of the text; offsets are relative to that copy, whose start an
    // element's name pointer and its offset tell.
    pugi::xml_node anchor = first;
    while (anchor && anchor.offset_debug() < 0) anchor = anchor.next_sibling();
    if (!anchor || anchor.type() == pugi::node_document) return;
    const char* base = (anchor.type() == pugi::node_element || anchor.type() == pugi::node_declaration ||
                        anchor.type() == pugi::node_pi)
                           ? anchor.name() - anchor.offset_debug()
                           : anchor.value() - anchor.offset_debug();
    XmlWalker(index, base).walk(document);
}

}  // namespace esi::navigate
