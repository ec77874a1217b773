#pragma once
// A small YAML writer for the importer: a tree of mappings, sequences and scalars rendered in
// block style (short mappings and lists of scalars in flow style), with every text quoted
// whenever a plain scalar could be read as something else (yes/no/on/off, ~, numbers, a leading
// '#', '*', '&', ': ' …). Output is deterministic: keys stay in insertion order.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace esi::import_detail {

class YNode {
public:
    enum class Kind { scalar, map, seq };

    YNode() : kind_(Kind::map) {}
    static YNode map() { return YNode(Kind::map); }
    static YNode seq() { return YNode(Kind::seq); }
    // A scalar already rendered (a number, a hex literal, true/false, a quoted text).
    static YNode raw(std::string text) {
        YNode n(Kind::scalar);
        n.scalar_ = std::move(text);
        return n;
    }
    static YNode text(std::string_view text);   // quoted when needed
    static YNode integer(std::int64_t value);
    static YNode unsigned_integer(std::uint64_t value);
    static YNode hex(std::uint64_t value, int digits = 4);  // 0x00AB
    static YNode boolean(bool value) { return raw(value ? "true" : "false"); }

    [[nodiscard]] Kind kind() const { return kind_; }
    [[nodiscard]] bool empty() const { return kind_ != Kind::scalar && items_.empty(); }

    // Mapping: adds a key (insertion order is output order).
    YNode& set(std::string_view key, YNode value);
    YNode& set_raw_key(std::string key, YNode value);  // key already rendered (0x6040, 1033)
    // Sequence: appends an item.
    YNode& push(YNode value);

    [[nodiscard]] std::string render() const;

private:
    explicit YNode(Kind kind) : kind_(kind) {}
    void render_block(std::string& out, int indent) const;
    [[nodiscard]] bool flow_fits(std::size_t budget, std::string& out) const;

    Kind kind_;
    std::string scalar_;
    std::vector<std::pair<std::string, YNode>> items_;  // map: (rendered key, value); seq: ("", value)
};

// A text as a YAML scalar: plain when that reads back as the same string, else double-quoted.
[[nodiscard]] std::string quote_text(std::string_view text);

}  // namespace esi::import_detail
