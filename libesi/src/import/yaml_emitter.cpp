#include "import/yaml_emitter.hpp"

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

// Decodes one UTF-8 code point at s[i]; returns its length (1 for an invalid byte, with cp = byte).
std::size_t decode(std::string_view s, std::size_t i, std::uint32_t& cp) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    std::size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (len == 0 || i + len > s.size()) {
        cp = c;
        return 1;
    }
    cp = len == 1 ? c : len == 2 ? (c & 0x1Fu) : len == 3 ? (c & 0x0Fu) : (c & 0x07u);
    for (std::size_t k = 1; k < len; ++k) {
        const unsigned char d = static_cast<unsigned char>(s[i + k]);
        if ((d & 0xC0) != 0x80) {
            cp = c;
            return 1;
        }
        cp = (cp << 6) | (d & 0x3Fu);
    }
    return len;
}

}  // namespace

std::string quote_text(std::string_view text) {
    if (plain_safe(text)) return std::string(text);
    std::string out = "\"";
    for (std::size_t i = 0; i < text.size();) {
        std::uint32_t cp = 0;
        const std::size_t len = decode(text, i, cp);
        char buffer[16];
        if (cp == '"') out += "\\\"";
        else if (cp == '\\') out += "\\\\";
        else if (cp == '\n') out += "\\n";
        else if (cp == '\t') out += "\\t";
        else if (cp == '\r') out += "\\r";
        else if (cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp < 0xA0) || (cp >= 0xD800 && cp < 0xE000) || cp == 0xFEFF ||
                 cp == 0xFFFE || cp == 0xFFFF || (len == 1 && cp >= 0x80)) {
            // Not printable in YAML (or not valid UTF-8): an escape keeps the code point.
            if (cp <= 0xFF) std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned>(cp));
            else std::snprintf(buffer, sizeof buffer, "\\u%04X", static_cast<unsigned>(cp));
            out += buffer;
        } else {
            out.append(text.substr(i, len));
        }
        i += len;
    }
    out += '"';
    return out;
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
