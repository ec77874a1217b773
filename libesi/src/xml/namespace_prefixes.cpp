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

}  // namespace

void report_undeclared_prefixes(const SourceText& source, const pugi::xml_document& parsed, const char* parse_buffer,
                                Diagnostics& diagnostics) {
    const pugi::xml_node root = parsed.document_element();
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
