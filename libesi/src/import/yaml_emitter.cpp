#include "import/yaml_emitter.hpp"

#include "esi/yaml/quote.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace esi::import_detail {

namespace {

bool special_word(std::string_view s) {
    // YAML 1.1 and 1.2 booleans and nulls: a plain scalar spelled like this is not read as text
    // by every tool (yes/no/on/off were booleans in YAML 1.1).
    static constexpr std::string_view words[] = {"y", "n", "yes", "no", "on", "off", "true", "false", "null", "~"};
    std::string lower(s);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return std::find(std::begin(words), std::end(words), lower) != std::end(words);
}

// Plain only for a conservative set: starts with a letter, then letters, digits, blanks and
// a few punctuation characters that mean nothing to YAML inside a plain scalar, no trailing blank.
bool plain_safe(std::string_view s) {
    if (s.empty() || s.size() > 200) return false;
    if (!std::isalpha(static_cast<unsigned char>(s.front()))) return false;
    if (s.back() == ' ') return false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (std::isalnum(c)) continue;
        if (c == ' ') {
            if (i + 1 < s.size() && (s[i + 1] == ' ' || s[i + 1] == '#')) return false;
            continue;
        }
        if (c == '_' || c == '.' || c == '-' || c == '/' || c == '(' || c == ')' || c == '+' || c == '=') continue;
        return false;
    }
    if (special_word(s)) return false;
    // 0x.., 1e5, .inf: anything a YAML 1.1/1.2 resolver could take for a number starts with a
    // digit, a sign or a dot, which the first test excludes; "Inf"/"NaN" are only special with a dot.
    return true;
}

}  // namespace

std::string quote_text(std::string_view text) {
    if (plain_safe(text)) return std::string(text);
    // One quoting for every YAML libesi writes; it escapes what the reader takes for a line
    // break (NEL, U+2028, U+2029) too. ESI text comes decoded from the XML reader, so it is UTF-8.
    return yaml::double_quoted(text).text;
}

YNode YNode::text(std::string_view t) { return raw(quote_text(t)); }
YNode YNode::integer(std::int64_t value) { return raw(std::to_string(value)); }
YNode YNode::unsigned_integer(std::uint64_t value) { return raw(std::to_string(value)); }
YNode YNode::hex(std::uint64_t value, int digits) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "0x%0*llX", digits, static_cast<unsigned long long>(value));
    return raw(buffer);
}

YNode& YNode::set(std::string_view key, YNode value) { return set_raw_key(quote_text(key), std::move(value)); }

YNode& YNode::set_raw_key(std::string key, YNode value) {
    items_.emplace_back(std::move(key), std::move(value));
    return items_.back().second;
}

YNode& YNode::push(YNode value) {
    items_.emplace_back(std::string(), std::move(value));
    return items_.back().second;
}

bool YNode::flow_fits(std::size_t budget, std::string& out) const {
    if (kind_ == Kind::scalar) {
        if (scalar_.size() > budget) return false;
        out += scalar_;
        return true;
    }
    out += kind_ == Kind::map ? "{ " : "[";
    if (kind_ == Kind::map && items_.empty()) out = out.substr(0, out.size() - 1) + "}";
    bool first = true;
    for (const auto& [key, value] : items_) {
        if (value.kind_ != Kind::scalar) return false;  // flow only one level deep
        if (!first) out += ", ";
        first = false;
        if (kind_ == Kind::map) out += key + ": ";
        out += value.scalar_;
        if (out.size() > budget) return false;
    }
    if (kind_ == Kind::map && !items_.empty()) out += " }";
    else if (kind_ == Kind::seq) out += "]";
    return out.size() <= budget;
}

void YNode::render_block(std::string& out, int indent) const {
    const std::string pad(static_cast<std::size_t>(indent), ' ');
    for (const auto& [key, value] : items_) {
        out += pad;
        if (kind_ == Kind::map) out += key + ":";
        else out += "-";
        if (value.kind_ == Kind::scalar) {
            out += " " + value.scalar_ + "\n";
            continue;
        }
        std::string flow;
        const std::size_t used = pad.size() + key.size() + 2;
        if (value.items_.empty() || value.flow_fits(used < 110 ? 110 - used : 20, flow)) {
            out += " " + (value.items_.empty() ? std::string(value.kind_ == Kind::map ? "{}" : "[]") : flow) + "\n";
            continue;
        }
        if (kind_ == Kind::seq && value.kind_ == Kind::map) {
            // "- key: value" with the other keys aligned under the first.
            std::string inner;
            value.render_block(inner, indent + 2);
            out += " " + inner.substr(static_cast<std::size_t>(indent) + 2);
            continue;
        }
        out += "\n";
        value.render_block(out, indent + 2);
    }
}

std::string YNode::render() const {
    std::string out;
    if (kind_ == Kind::scalar) return scalar_ + "\n";
    render_block(out, 0);
    return out;
}

}  // namespace esi::import_detail
