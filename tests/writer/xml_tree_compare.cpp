#include "writer/xml_tree_compare.hpp"

#include <algorithm>
#include <pugixml.hpp>
#include <unordered_map>

#include "esi/number.hpp"

namespace esi::test {

std::string_view to_string(TreeDifference::Kind kind) {
    switch (kind) {
        case TreeDifference::Kind::missing_element: return "element missing";
        case TreeDifference::Kind::added_element: return "element added";
        case TreeDifference::Kind::missing_attribute: return "attribute missing";
        case TreeDifference::Kind::added_attribute: return "attribute added";
        case TreeDifference::Kind::changed_attribute: return "attribute changed";
        case TreeDifference::Kind::changed_text: return "text changed";
    }
    return "?";
}

namespace {

// xs:hexBinary elements of ETG.2000: compared without whitespace and case.
bool is_hex_binary_element(std::string_view name) {
    return name == "Data" || name == "ConfigData" || name == "BootStrap" || name == "ImageData16x14" || name == "DefaultData" ||
           name == "MinData" || name == "MaxData";
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// One spelling per meaning: "n:<decimal>" for numbers and booleans, "h:<HEX>" for hexBinary,
// "s:<trimmed text>" for everything else.
std::string canonical(std::string_view value, bool hex_binary) {
    const std::string_view t = trim(value);
    if (hex_binary) {
        std::string out = "h:";
        for (const char c : t)
            if (!is_space(c)) out.push_back(c >= 'a' && c <= 'f' ? static_cast<char>(c - 'a' + 'A') : c);
        return out;
    }
    if (!t.empty()) {
        const ParsedNumber n = parse_number(t);
        if (n.ok()) return "n:" + format_decimal(n.value);
        if (t == "true") return "n:1";
        if (t == "false") return "n:0";
    }
    return "s:" + std::string(t);
}

std::string text_of(const pugi::xml_node node) {
    std::string text;
    for (const auto c : node.children())
        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) text += c.value();
    return text;
}

std::uint64_t fnv(std::uint64_t h, std::string_view s) {
    for (const char c : s) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    h ^= 0xFF;  // separator
    h *= 1099511628211ull;
    return h;
}

class Comparer {
public:
    Comparer(std::string_view original, std::size_t limit) : limit_(limit) {
        line_starts_.push_back(0);
        for (std::size_t i = 0; i < original.size(); ++i)
            if (original[i] == '\n') line_starts_.push_back(i + 1);
    }

    void compare(const pugi::xml_node a, const pugi::xml_node b, const std::string& path) {
        if (out_.size() >= limit_) return;
        const bool hex = is_hex_binary_element(a.name());
        // attributes
        for (const auto attr : a.attributes()) {
            const auto other = b.attribute(attr.name());
            if (!other) add(TreeDifference::Kind::missing_attribute, path, attr.name(), a);
            else if (canonical(attr.value(), false) != canonical(other.value(), false))
                add(TreeDifference::Kind::changed_attribute, path,
                    std::string(attr.name()) + ": '" + attr.value() + "' vs '" + other.value() + "'", a);
        }
        for (const auto attr : b.attributes())
            if (!a.attribute(attr.name())) add(TreeDifference::Kind::added_attribute, path, attr.name(), a);
        // text
        const std::string ta = text_of(a);
        const std::string tb = text_of(b);
        if (canonical(ta, hex) != canonical(tb, hex))
            add(TreeDifference::Kind::changed_text, path,
                "'" + std::string(trim(ta)).substr(0, 80) + "' vs '" + std::string(trim(tb)).substr(0, 80) + "'", a);
        // children as multisets
        std::vector<pugi::xml_node> ca;
        std::vector<pugi::xml_node> cb;
        for (const auto c : a.children())
            if (c.type() == pugi::node_element) ca.push_back(c);
        for (const auto c : b.children())
            if (c.type() == pugi::node_element) cb.push_back(c);
        std::unordered_multimap<std::uint64_t, std::size_t> by_hash;
        for (std::size_t i = 0; i < cb.size(); ++i) by_hash.emplace(hash(cb[i]), i);
        std::vector<bool> b_used(cb.size(), false);
        std::vector<pugi::xml_node> a_left;
        for (const auto c : ca) {
            const auto range = by_hash.equal_range(hash(c));
            if (range.first == range.second) {
                a_left.push_back(c);
                continue;
            }
            b_used[range.first->second] = true;
            by_hash.erase(range.first);
        }
        std::vector<pugi::xml_node> b_left;
        for (std::size_t i = 0; i < cb.size(); ++i)
            if (!b_used[i]) b_left.push_back(cb[i]);
        // Pair what is left by name, in document order, and say what differs inside.
        std::vector<bool> b_paired(b_left.size(), false);
        for (const auto c : a_left) {
            const std::string child_path = path + "/" + c.name();
            bool paired = false;
            for (std::size_t i = 0; i < b_left.size(); ++i) {
                if (b_paired[i] || std::string_view(b_left[i].name()) != c.name()) continue;
                b_paired[i] = true;
                paired = true;
                compare(c, b_left[i], child_path);
                break;
            }
            if (!paired) add(TreeDifference::Kind::missing_element, child_path, "", c);
        }
        for (std::size_t i = 0; i < b_left.size(); ++i)
            if (!b_paired[i]) add(TreeDifference::Kind::added_element, path + "/" + b_left[i].name(), "", {});
    }

    std::vector<TreeDifference> take() { return std::move(out_); }

private:
    std::uint64_t hash(const pugi::xml_node n) {
        if (const auto it = memo_.find(n.internal_object()); it != memo_.end()) return it->second;
        std::uint64_t h = fnv(14695981039346656037ull, n.name());
        std::vector<std::uint64_t> parts;
        for (const auto a : n.attributes()) parts.push_back(fnv(fnv(7, a.name()), canonical(a.value(), false)));
        std::sort(parts.begin(), parts.end());
        for (const auto p : parts) h = fnv(h, std::string_view(reinterpret_cast<const char*>(&p), sizeof p));
        h = fnv(h, canonical(text_of(n), is_hex_binary_element(n.name())));
        parts.clear();
        for (const auto c : n.children())
            if (c.type() == pugi::node_element) parts.push_back(hash(c));
        std::sort(parts.begin(), parts.end());
        for (const auto p : parts) h = fnv(h, std::string_view(reinterpret_cast<const char*>(&p), sizeof p));
        memo_.emplace(n.internal_object(), h);
        return h;
    }

    void add(TreeDifference::Kind kind, const std::string& path, std::string detail, const pugi::xml_node where) {
        if (out_.size() >= limit_) return;
        std::uint32_t line = 0;
        if (where && where.offset_debug() >= 0) {
            const auto offset = static_cast<std::size_t>(where.offset_debug());
            line = static_cast<std::uint32_t>(std::upper_bound(line_starts_.begin(), line_starts_.end(), offset) - line_starts_.begin());
        }
        out_.push_back(TreeDifference{kind, path, std::move(detail), line});
    }

    std::size_t limit_;
    std::vector<std::size_t> line_starts_;
    std::unordered_map<const void*, std::uint64_t> memo_;
    std::vector<TreeDifference> out_;
};

}  // namespace

TreeComparison compare_xml_trees(std::string_view original, std::string_view rewritten, std::size_t limit) {
    TreeComparison result;
    pugi::xml_document a;
    pugi::xml_document b;
    const auto ra = a.load_buffer(original.data(), original.size(), pugi::parse_default, pugi::encoding_utf8);
    const auto rb = b.load_buffer(rewritten.data(), rewritten.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!ra || !rb) {
        result.error = !ra ? std::string("original: ") + ra.description() : std::string("rewritten: ") + rb.description();
        return result;
    }
    result.parsed = true;
    const auto root_a = a.document_element();
    const auto root_b = b.document_element();
    Comparer comparer(original, limit);
    if (std::string_view(root_a.name()) != root_b.name()) {
        result.differences.push_back({TreeDifference::Kind::missing_element, root_a.name(), "root differs", 1});
        return result;
    }
    comparer.compare(root_a, root_b, root_a.name());
    result.differences = comparer.take();
    return result;
}

}  // namespace esi::test
