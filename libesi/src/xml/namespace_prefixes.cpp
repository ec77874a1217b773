#include "xml/namespace_prefixes.hpp"

#include <cstring>
#include <optional>
#include <set>
#include <string>

namespace esi {

namespace {

// The prefix of a qualified name ("xsi" of "xsi:type"); empty when it has none.
std::string_view prefix_of(const char* name) {
    const std::string_view n = name;
    const std::size_t colon = n.find(':');
    return colon == std::string_view::npos ? std::string_view() : n.substr(0, colon);
}

bool declared(pugi::xml_node element, std::string_view prefix) {
    // "xml" is bound by the XML namespaces recommendation itself, "xmlns" is the declaration syntax.
    if (prefix == "xml" || prefix == "xmlns") return true;
    const std::string declaration = "xmlns:" + std::string(prefix);
    for (pugi::xml_node n = element; n && n.type() == pugi::node_element; n = n.parent())
        if (n.attribute(declaration.c_str())) return true;
    return false;
}

class PrefixCheck {
public:
    PrefixCheck(const SourceText& source, const char* buffer, pugi::xml_node root, Diagnostics& diagnostics)
        : source_(source), buffer_(buffer), root_(root), diagnostics_(diagnostics) {}

    void check(pugi::xml_node element, const char* name) {
        const std::string_view prefix = prefix_of(name);
        if (prefix.empty() || reported_.count(prefix) || declared(element, prefix)) return;
        reported_.emplace(prefix);
        std::string message = "the prefix '" + excerpt(prefix) + "' of '" + excerpt(name) + "' is not declared (no xmlns:" +
                              excerpt(prefix) + " on this or an enclosing element); namespace-aware XML readers reject the file";
        if (prefix == "xsi") message += "; declare xmlns:xsi=\"" + std::string(xml_schema_instance_namespace) + "\" on the root element";
        Diagnostic& d = diagnostics_.emplace(Severity::error, "xml-undeclared-prefix", std::move(message), source_.path(), position(name));
        if (prefix == "xsi") d.fix = declare_xsi();
    }

private:
    bool ours(const char* p) const { return p >= buffer_ && p < buffer_ + source_.text().size(); }

    SourcePos position(const char* name) const {
        return ours(name) ? source_.position_of(static_cast<std::size_t>(name - buffer_)) : SourcePos{};
    }

    // Inserted right after the root element's name, where it cannot split anything.
    std::optional<Fix> declare_xsi() const {
        const char* name = root_.name();
        if (!ours(name)) return std::nullopt;
        const std::size_t at = static_cast<std::size_t>(name - buffer_) + std::strlen(name);
        return Fix{"declare xmlns:xsi on the root element",
                   {TextEdit{at, 0, " xmlns:xsi=\"" + std::string(xml_schema_instance_namespace) + "\""}}};
    }

    const SourceText& source_;
    const char* buffer_;
    pugi::xml_node root_;
    Diagnostics& diagnostics_;
    std::set<std::string, std::less<>> reported_;
};

bool name_start(char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u >= 'A' && u <= 'Z') || (u >= 'a' && u <= 'z') || u == '_' || u >= 0x80;
}

bool name_char(char c) { return name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'; }

// Whether every prefixed name the text may hold uses a prefix that the root declares, which then
// holds everywhere: the walk over every element (most of this check's cost) is not needed. A
// prefixed name in markup follows '<' (an element) or a blank (an attribute) and has a name
// character right after its colon; text such as "Hinweis: …" seldom looks like that, and when it
// does, the walk decides.
bool only_prefixes_of_the_root(std::string_view text, pugi::xml_node root) {
    std::set<std::string_view, std::less<>> declared_on_root;
    for (const pugi::xml_attribute a : root.attributes()) {
        const std::string_view name = a.name();
        if (name.starts_with("xmlns:")) declared_on_root.insert(name.substr(6));
    }
    for (std::size_t colon = text.find(':'); colon != std::string_view::npos; colon = text.find(':', colon + 1)) {
        if (colon + 1 >= text.size() || !name_start(text[colon + 1])) continue;
        std::size_t start = colon;
        while (start > 0 && name_char(text[start - 1])) --start;
        if (start == colon || start == 0 || !name_start(text[start])) continue;
        const char before = text[start - 1];
        if (before != '<' && before != ' ' && before != '\t' && before != '\n' && before != '\r') continue;
        const std::string_view prefix = text.substr(start, colon - start);
        if (prefix != "xml" && prefix != "xmlns" && !declared_on_root.count(prefix)) return false;
    }
    return true;
}

}  // namespace

void report_undeclared_prefixes(const SourceText& source, const pugi::xml_document& parsed, const char* parse_buffer,
                                Diagnostics& diagnostics) {
    const pugi::xml_node root = parsed.document_element();
    if (only_prefixes_of_the_root(source.text(), root)) return;
    PrefixCheck check(source, parse_buffer, root, diagnostics);
    for (pugi::xml_node n = root; n;) {
        if (n.type() == pugi::node_element) {
            check.check(n, n.name());
            for (const pugi::xml_attribute a : n.attributes()) check.check(n, a.name());
        }
        // Depth first, in document order, without recursion.
        if (pugi::xml_node child = n.first_child()) {
            n = child;
            continue;
        }
        while (n && n != root && !n.next_sibling()) n = n.parent();
        if (!n || n == root) break;
        n = n.next_sibling();
    }
}

}  // namespace esi
