#pragma once
// Typed access to YAML nodes, for every YAML file libesi reads (device sources, .esi-lint.yaml).
// Every accessor checks the node's kind and range and reports a located diagnostic instead of
// throwing; callers get nullopt and carry on, so one run reports every problem of a file.

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "esi/yaml/tree.hpp"

#include "esi/model/typed_value.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/common.hpp"
#include "esi/model/rare_optional.hpp"
#include "esi/number.hpp"
#include "esi/yaml/format_keys.hpp"

namespace esi::yaml {

// "; did you mean 'x'?" for a close candidate, else empty (a two-letter word is not "close" to
// every other two-letter word).
[[nodiscard]] std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);
[[nodiscard]] inline SourcePos pos_of(const Node& node) { return node.pos(); }

// A mapping read once, keys in document order.
class Fields {
public:
    Fields() = default;
    explicit Fields(const Node& node);

    [[nodiscard]] const Node* find(std::string_view key) const;
    [[nodiscard]] bool has(std::string_view key) const { return find(key) != nullptr; }
    [[nodiscard]] const Node* key_node(std::string_view key) const;
    [[nodiscard]] const Node& node() const { return node_; }
    [[nodiscard]] SourcePos pos() const { return pos_of(node_); }

    struct Item {
        std::string_view key;  // into the tree, which outlives the Fields
        Node key_node;
        Node value;
    };
    [[nodiscard]] const std::vector<Item>& items() const { return items_; }

private:
    Node node_;
    std::vector<Item> items_;
};

class Reader {
public:
    Reader(std::string path, Diagnostics& diagnostics) : path_(std::move(path)), diagnostics_(diagnostics) {}

    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] Diagnostics& diagnostics() { return diagnostics_; }

    Diagnostic& error(SourcePos pos, std::string rule, std::string message);
    Diagnostic& error(const Node& at, std::string rule, std::string message) {
        return error(pos_of(at), std::move(rule), std::move(message));
    }
    Diagnostic& warning(SourcePos pos, std::string rule, std::string message);

    // A mapping whose keys must come from `context`; unknown keys are reported with a
    // did-you-mean. nullopt (and a diagnostic) when the node is not a mapping.
    std::optional<Fields> mapping(const Node& node, Context context, std::string_view what);
    // The same with the allowed keys given directly (files other than the device source).
    std::optional<Fields> mapping(const Node& node, std::span<const std::string_view> keys, std::string_view what);
    // Reports a required key that is missing.
    bool require(const Fields& fields, std::string_view key, std::string_view what);

    // A sequence's items; a lone non-sequence value is an error.
    std::optional<std::vector<Node>> sequence(const Node& node, std::string_view what);

    std::optional<std::string> text(const Node& node, std::string_view what);
    std::optional<bool> boolean(const Node& node, std::string_view what);
    // Integers: decimal, 0x/#x hex, 0b binary, 0o octal, with an optional sign.
    std::optional<Number> number(const Node& node, std::string_view what);
    template <class T>
    std::optional<T> integer(const Node& node, std::string_view what, T min = std::numeric_limits<T>::min(),
                             T max = std::numeric_limits<T>::max());
    std::optional<double> real(const Node& node, std::string_view what);
    // hexBinary: pairs of hex digits, blanks allowed between them.
    std::optional<HexData> hex(const Node& node, std::string_view what);
    // A string (one Name without LcId) or a mapping of languages (en, de …, or a numeric LcId).
    Names names(const Node& node, std::string_view what);
    std::optional<SourceValue> scalar_value(const Node& node, std::string_view what);

    // Convenience: read `key` of a mapping into an optional field when present.
    template <class T>
    void optional_integer(const Fields& f, std::string_view key, std::optional<T>& out, T min = std::numeric_limits<T>::min(),
                          T max = std::numeric_limits<T>::max()) {
        if (const Node* n = f.find(key)) out = integer<T>(*n, key, min, max);
    }
    void optional_bool(const Fields& f, std::string_view key, std::optional<bool>& out) {
        if (const Node* n = f.find(key)) out = boolean(*n, key);
    }
    void optional_text(const Fields& f, std::string_view key, std::optional<std::string>& out) {
        if (const Node* n = f.find(key)) out = text(*n, key);
    }
    void optional_text(const Fields& f, std::string_view key, RareOptional<std::string>& out) {
        if (const Node* n = f.find(key)) out = text(*n, key);
    }

private:
    std::optional<Number> parse_integer(const Node& node, std::string_view what, bool report);

    std::string path_;
    Diagnostics& diagnostics_;
};

template <class T>
std::optional<T> Reader::integer(const Node& node, std::string_view what, T min, T max) {
    const std::optional<Number> n = number(node, what);
    if (!n) return std::nullopt;
    bool in_range = false;
    if constexpr (std::is_signed_v<T>) {
        const auto v = n->as_int64();
        in_range = v && *v >= static_cast<std::int64_t>(min) && *v <= static_cast<std::int64_t>(max);
        if (in_range) return static_cast<T>(*v);
    } else {
        const auto v = n->as_uint64();
        in_range = v && *v >= static_cast<std::uint64_t>(min) && *v <= static_cast<std::uint64_t>(max);
        if (in_range) return static_cast<T>(*v);
    }
    auto bound = [](T v) {
        if constexpr (std::is_signed_v<T>) return format_decimal(Number::from_signed(static_cast<std::int64_t>(v)));
        else if (v > 0xFFFF) return "0x" + format_hex(static_cast<std::uint64_t>(v)).substr(2);
        else return std::to_string(static_cast<std::uint64_t>(v));
    };
    error(node, "yaml-number-range",
          "'" + std::string(what) + "' is " + format_decimal(*n) + ", out of range " + bound(min) + ".." + bound(max));
    return std::nullopt;
}

}  // namespace esi::yaml
