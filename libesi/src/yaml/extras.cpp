#include "yaml/extras.hpp"

#include <pugixml.hpp>

#include "esi/xml/well_formed.hpp"
#include "esi/xml/xinclude.hpp"

namespace esi::yaml {

namespace {

constexpr std::size_t max_xml_depth = 64;

XmlElement convert(const pugi::xml_node n, std::string after, SourcePos pos, std::size_t depth) {
    XmlElement e;
    e.name = n.name();
    e.after = std::move(after);
    e.pos = pos;
    for (const auto a : n.attributes()) e.attributes.push_back({a.name(), a.value()});
    if (depth >= max_xml_depth) return e;
    std::string previous;
    for (const auto c : n.children()) {
        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
            e.text += c.value();
        } else if (c.type() == pugi::node_element) {
            e.children.push_back(convert(c, previous, pos, depth + 1));
            previous = c.name();
        }
    }
    return e;
}

void read_element(Reader& reader, const Node& text_node, const std::string& after, Extras& out, std::string_view what) {
    const std::optional<std::string> text = reader.text(text_node, what);
    if (!text) return;
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(text->data(), text->size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed) {
        reader.error(text_node, "yaml-xml",
                     "'" + std::string(what) + "' is not well-formed XML at character " + std::to_string(parsed.offset + 1) +
                         ": " + parsed.description());
        return;
    }
    // What pugixml tolerates (a repeated attribute, '<' in a value, ...) would be written into
    // the generated ESI file as it is.
    if (const auto fault = find_content_fault(*text)) {
        reader.error(text_node, "yaml-xml",
                     "'" + std::string(what) + "' is not well-formed XML at character " + std::to_string(fault->offset + 1) + ": " +
                         fault->message);
        return;
    }
    for (const pugi::xml_node top : doc.children()) {
        for (const pugi::xml_node element : find_xinclude_elements(*text, top)) {
            reader.error(text_node, "yaml-xml", "'" + std::string(what) + "' holds " + describe_xinclude(element));
            return;
        }
    }
    std::string previous = after;
    bool any = false;
    for (const auto c : doc.children()) {
        if (c.type() != pugi::node_element) continue;
        out.elements.push_back(convert(c, previous, pos_of(text_node), 1));
        previous = c.name();
        any = true;
    }
    if (!any) reader.error(text_node, "yaml-xml", "'" + std::string(what) + "' holds no XML element");
}

}  // namespace

void read_extras(Reader& reader, const Node& node, Extras& out, std::string_view what) {
    const auto fields = reader.mapping(node, Context::xml, what);
    if (!fields) return;
    if (const Node* attributes = fields->find("attributes")) {
        if (!attributes->IsMap()) {
            reader.error(*attributes, "yaml-type", "'attributes' must map XML attribute names to values");
        } else {
            for (auto it = attributes->begin(); it != attributes->end(); ++it) {
                const auto name = reader.text(it->first, "attribute name");
                const auto value = reader.text(it->second, "attribute value");
                if (name && value) out.attributes.push_back({*name, *value});
            }
        }
    }
    if (const Node* elements = fields->find("elements")) {
        const auto items = reader.sequence(*elements, "elements");
        if (!items) return;
        for (const auto& item : *items) {
            if (item.IsMap()) {
                const auto element = reader.mapping(item, Context::xml_element, "an xml element");
                if (!element || !reader.require(*element, "xml", "an xml element")) continue;
                std::string after;
                if (const Node* a = element->find("after")) after = reader.text(*a, "after").value_or("");
                read_element(reader, *element->find("xml"), after, out, "xml");
            } else {
                read_element(reader, item, "", out, "elements");
            }
        }
    }
}

}  // namespace esi::yaml
