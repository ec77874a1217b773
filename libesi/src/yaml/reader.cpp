#include "esi/yaml/reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "esi/model/language.hpp"
#include "esi/text_distance.hpp"

namespace esi::yaml {

std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates) {
    const std::string s = closest_match(word, candidates);
    if (s.empty() || edit_distance(word, s) >= std::max<std::size_t>(word.size(), 1)) return {};
    return "; did you mean '" + s + "'?";
}

Fields::Fields(const Node& node) : node_(node) {
    items_.reserve(node.size());
    for (auto it = node.begin(); it != node.end(); ++it) {
        Item item;
        item.key_node = it->first;
        item.value = it->second;
        if (it->first.IsScalar()) item.key = it->first.Scalar();
        items_.push_back(std::move(item));
    }
}

const Node* Fields::find(std::string_view key) const {
    for (const auto& item : items_)
        if (item.key == key) return &item.value;
    return nullptr;
}

const Node* Fields::key_node(std::string_view key) const {
    for (const auto& item : items_)
        if (item.key == key) return &item.key_node;
    return nullptr;
}

Diagnostic& Reader::error(SourcePos pos, std::string rule, std::string message) {
    return diagnostics_.emplace(Severity::error, std::move(rule), std::move(message), path_, pos);
}

Diagnostic& Reader::warning(SourcePos pos, std::string rule, std::string message) {
    return diagnostics_.emplace(Severity::warning, std::move(rule), std::move(message), path_, pos);
}

namespace {

std::string_view kind_name(const Node& node) {
    if (node.IsNull()) return "nothing";
    if (node.IsMap()) return "a mapping";
    if (node.IsSequence()) return "a list";
    return "a scalar";
}

}  // namespace

std::optional<Fields> Reader::mapping(const Node& node, Context context, std::string_view what) {
    return mapping(node, keys_of(context).keys, what);
}

std::optional<Fields> Reader::mapping(const Node& node, std::span<const std::string_view> keys, std::string_view what) {
    if (!node.IsMap()) {
        error(node, "yaml-type", "'" + std::string(what) + "' must be a mapping, not " + std::string(kind_name(node)));
        return std::nullopt;
    }
    Fields fields(node);
    for (const auto& item : fields.items()) {
        if (!item.key_node.IsScalar()) {
            error(item.key_node, "yaml-type", "keys of '" + std::string(what) + "' must be plain words");
            continue;
        }
        if (std::find(keys.begin(), keys.end(), item.key) != keys.end()) continue;
        std::string message = "unknown key '" + std::string(item.key) + "' in " + std::string(what);
        message += did_you_mean(item.key, keys);
        error(item.key_node, "yaml-unknown-key", message);
    }
    return fields;
}

bool Reader::require(const Fields& fields, std::string_view key, std::string_view what) {
    if (fields.has(key)) return true;
    error(fields.node(), "yaml-missing-key", std::string(what) + " needs '" + std::string(key) + "'");
    return false;
}

std::optional<std::vector<Node>> Reader::sequence(const Node& node, std::string_view what) {
    if (!node.IsSequence()) {
        error(node, "yaml-type", "'" + std::string(what) + "' must be a list, not " + std::string(kind_name(node)));
        return std::nullopt;
    }
    std::vector<Node> items;
    items.reserve(node.size());
    for (const auto& item : node) items.push_back(item);
    return items;
}

std::optional<std::string> Reader::text(const Node& node, std::string_view what) {
    if (!node.IsScalar()) {
        error(node, "yaml-type", "'" + std::string(what) + "' must be text, not " + std::string(kind_name(node)));
        return std::nullopt;
    }
    return node.Scalar();
}

std::optional<bool> Reader::boolean(const Node& node, std::string_view what) {
    if (node.IsScalar()) {
        std::string v = node.Scalar();
        std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (v == "true" || v == "1") return true;
        if (v == "false" || v == "0") return false;
    }
    error(node, "yaml-type",
          "'" + std::string(what) + "' must be true or false, not " +
              (node.IsScalar() ? "'" + node.Scalar() + "'" : std::string(kind_name(node))));
    return std::nullopt;
}

namespace {

// 0b/0o prefixes (YAML 1.2 core schema spellings) on top of what parse_number knows.
std::optional<Number> parse_radix(std::string_view text, int base) {
    bool negative = false;
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
        negative = text.front() == '-';
        text.remove_prefix(1);
    }
    if (text.size() < 3 || text[0] != '0') return std::nullopt;
    const char marker = static_cast<char>(std::tolower(static_cast<unsigned char>(text[1])));
    if ((base == 2 && marker != 'b') || (base == 8 && marker != 'o')) return std::nullopt;
    text.remove_prefix(2);
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return Number{value, negative && value != 0};
}

}  // namespace

std::optional<Number> Reader::parse_integer(const Node& node, std::string_view what, bool report) {
    if (!node.IsScalar()) {
        if (report)
            error(node, "yaml-type", "'" + std::string(what) + "' must be a number, not " + std::string(kind_name(node)));
        return std::nullopt;
    }
    const std::string& s = node.Scalar();
    const ParsedNumber parsed = parse_number(s);
    if (parsed.ok()) return parsed.value;
    if (parsed.error == NumberError::overflow) {
        if (report) error(node, "yaml-number-range", "'" + std::string(what) + "' is " + s + ", beyond 64 bits");
        return std::nullopt;
    }
    if (auto b = parse_radix(trim(s), 2)) return b;
    if (auto o = parse_radix(trim(s), 8)) return o;
    if (report) error(node, "yaml-type", "'" + std::string(what) + "' must be a number; '" + s + "' is not an integer");
    return std::nullopt;
}

std::optional<Number> Reader::number(const Node& node, std::string_view what) { return parse_integer(node, what, true); }

std::optional<double> Reader::real(const Node& node, std::string_view what) {
    if (node.IsScalar()) {
        const std::string_view s = trim(node.Scalar());
        if (auto i = parse_integer(node, what, false)) {
            if (const auto v = i->as_int64()) return static_cast<double>(*v);
            return static_cast<double>(i->magnitude);
        }
        double value = 0;
        const char* begin = s.data();
        if (!s.empty() && s.front() == '+') ++begin;
        const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), value);
        if (ec == std::errc() && end == s.data() + s.size() && std::isfinite(value)) return value;
    }
    error(node, "yaml-type",
          "'" + std::string(what) + "' must be a number, not " +
              (node.IsScalar() ? "'" + node.Scalar() + "'" : std::string(kind_name(node))));
    return std::nullopt;
}

std::optional<HexData> Reader::hex(const Node& node, std::string_view what) {
    if (!node.IsScalar()) {
        error(node, "yaml-type", "'" + std::string(what) + "' must be hex bytes such as 0800CC00, not " + std::string(kind_name(node)));
        return std::nullopt;
    }
    HexData out;
    out.pos = pos_of(node);
    const std::string& s = node.Scalar();
    for (char c : s) {
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
        if (!std::isxdigit(static_cast<unsigned char>(c))) {
            error(node, "yaml-type",
                  "'" + std::string(what) + "': '" + s + "' is not hex bytes (digits 0-9 and A-F, two per byte, no 0x prefix)");
            return std::nullopt;
        }
        out.text.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    }
    if (out.text.size() % 2 != 0) {
        error(node, "yaml-type", "'" + std::string(what) + "': '" + s + "' has an odd number of hex digits; write two per byte");
        return std::nullopt;
    }
    return out;
}

Names Reader::names(const Node& node, std::string_view what) {
    Names out;
    if (node.IsNull()) return out;  // `name: null`: no Name element (an imported file without one)
    if (node.IsScalar()) {
        out.push_back(LocalizedText{node.Scalar(), std::nullopt, pos_of(node)});
        return out;
    }
    if (!node.IsMap()) {
        error(node, "yaml-type",
              "'" + std::string(what) + "' must be text or a mapping of languages (en: …, de: …), not " +
                  std::string(kind_name(node)));
        return out;
    }
    for (auto it = node.begin(); it != node.end(); ++it) {
        const Node key = it->first;
        const Node value = it->second;
        if (!key.IsScalar()) {
            error(key, "yaml-type", "languages of '" + std::string(what) + "' are codes such as en or de");
            continue;
        }
        LocalizedText t;
        t.pos = pos_of(value);
        const std::string code = key.Scalar();
        bool known = false;
        if (const auto lcid = lcid_of_language(code)) {
            t.lcid = *lcid;
            known = true;
        }
        if (!known) {
            const ParsedNumber n = parse_number(code);
            if (n.ok() && !n.value.negative && n.value.magnitude <= 0xFFFF) {
                t.lcid = static_cast<std::uint32_t>(n.value.magnitude);
                known = true;
            }
        }
        if (!known) {
            std::vector<std::string_view> codes;
            for (const auto& l : languages) codes.push_back(l.code);
            std::string message = "unknown language '" + code + "' in '" + std::string(what) + "' (use a code such as en or de, or a numeric LcId)";
            message += did_you_mean(code, codes);
            error(key, "yaml-unknown-key", message);
            continue;
        }
        if (!value.IsScalar()) {
            error(value, "yaml-type", "'" + std::string(what) + "." + code + "' must be text");
            continue;
        }
        t.text = value.Scalar();
        out.push_back(std::move(t));
    }
    return out;
}

std::optional<SourceValue> Reader::scalar_value(const Node& node, std::string_view what) {
    if (!node.IsScalar()) {
        error(node, "yaml-type", "'" + std::string(what) + "' must be a single value, not " + std::string(kind_name(node)));
        return std::nullopt;
    }
    SourceValue v;
    v.pos = pos_of(node);
    v.text = node.Scalar();
    const bool quoted = node.quoted();
    if (!quoted) {
        if (auto i = parse_integer(node, what, false)) {
            v.kind = SourceValue::Kind::integer;
            v.integer = *i;
            v.real = i->negative ? -static_cast<double>(i->magnitude) : static_cast<double>(i->magnitude);
            return v;
        }
        std::string lower(trim(v.text));
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (lower == "true" || lower == "false") {
            v.kind = SourceValue::Kind::boolean;
            v.boolean = lower == "true";
            return v;
        }
        const std::string_view s = trim(v.text);
        double d = 0;
        const char* begin = s.data();
        if (!s.empty() && s.front() == '+') ++begin;
        const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), d);
        if (!s.empty() && ec == std::errc() && end == s.data() + s.size() && std::isfinite(d)) {
            v.kind = SourceValue::Kind::real;
            v.real = d;
            return v;
        }
    }
    v.kind = SourceValue::Kind::text;
    return v;
}

}  // namespace esi::yaml
