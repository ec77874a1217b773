#include "esi/model/common.hpp"

#include "esi/model/language.hpp"
#include "esi/number.hpp"

namespace esi {

const std::string& primary_text(const Names& names) {
    static const std::string empty;
    if (names.empty()) return empty;
    if (const LocalizedText* english = find_lcid(names, default_lcid)) return english->text;
    for (const auto& n : names)
        if (!n.lcid) return n.text;
    return names.front().text;
}

const LocalizedText* find_lcid(const Names& names, std::uint32_t lcid) {
    for (const auto& n : names)
        if (n.lcid == lcid) return &n;
    return nullptr;
}

namespace {
int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}
}  // namespace

bool HexData::valid() const {
    if (text.size() % 2 != 0) return false;
    for (char c : text)
        if (hex_value(c) < 0) return false;
    return true;
}

std::optional<std::vector<std::uint8_t>> HexData::bytes() const {
    if (!valid()) return std::nullopt;
    std::vector<std::uint8_t> out(text.size() / 2);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<std::uint8_t>(hex_value(text[2 * i]) * 16 + hex_value(text[2 * i + 1]));
    return out;
}

HexData HexData::from_bytes(const std::vector<std::uint8_t>& bytes) {
    static constexpr char digits[] = "0123456789ABCDEF";
    HexData out;
    out.text.reserve(bytes.size() * 2);
    for (std::uint8_t b : bytes) {
        out.text.push_back(digits[b >> 4]);
        out.text.push_back(digits[b & 0xF]);
    }
    return out;
}

const XmlAttribute* XmlElement::attribute(std::string_view attribute_name) const {
    for (const auto& a : attributes)
        if (a.name == attribute_name) return &a;
    return nullptr;
}

const XmlElement* XmlElement::child(std::string_view child_name) const {
    for (const auto& c : children)
        if (c.name == child_name) return &c;
    return nullptr;
}

const XmlElement* XmlElement::find(std::string_view path) const {
    const XmlElement* current = this;
    while (current && !path.empty()) {
        const auto slash = path.find('/');
        current = current->child(path.substr(0, slash));
        path = slash == std::string_view::npos ? std::string_view{} : path.substr(slash + 1);
    }
    return current;
}

bool same_content(const XmlElement& a, const XmlElement& b) {
    if (a.name != b.name || a.attributes != b.attributes || trim(a.text) != trim(b.text) ||
        a.children.size() != b.children.size())
        return false;
    for (std::size_t i = 0; i < a.children.size(); ++i)
        if (!same_content(a.children[i], b.children[i])) return false;
    return true;
}

const XmlAttribute* Extras::attribute(std::string_view name) const {
    for (const auto& a : attributes)
        if (a.name == name) return &a;
    return nullptr;
}

const XmlElement* Extras::element(std::string_view name) const {
    for (const auto& e : elements)
        if (e.name == name) return &e;
    return nullptr;
}

const XmlElement* Extras::find(std::string_view path) const {
    const auto slash = path.find('/');
    const XmlElement* first = element(path.substr(0, slash));
    if (!first || slash == std::string_view::npos) return first;
    return first->find(path.substr(slash + 1));
}

}  // namespace esi
