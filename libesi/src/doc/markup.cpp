#include "doc/markup.hpp"

#include <algorithm>
#include <cstdio>

namespace esi::doc {

void append_escaped(std::string& out, std::string_view text) {
    std::size_t run = 0;  // start of the run of bytes that need no escaping
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char* entity = nullptr;
        switch (text[i]) {
            case '&': entity = "&amp;"; break;
            case '<': entity = "&lt;"; break;
            case '>': entity = "&gt;"; break;
            case '"': entity = "&quot;"; break;
            default: continue;
        }
        out.append(text.substr(run, i - run));
        out.append(entity);
        run = i + 1;
    }
    out.append(text.substr(run));
}

std::string escaped(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    append_escaped(out, text);
    return out;
}

std::string hex(std::uint64_t value, int digits) {
    char buffer[24];
    std::snprintf(buffer, sizeof buffer, "0x%0*llX", digits, static_cast<unsigned long long>(value));
    return buffer;
}

std::string index_text(std::uint32_t index, std::uint32_t subindex) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "0x%04X:%02X", index, subindex);
    return buffer;
}

namespace {

// Length of the UTF-8 sequence starting with `lead` (1 for stray continuation bytes, so a walk
// always advances).
std::size_t sequence_length(unsigned char lead) {
    if (lead < 0xC0) return 1;
    if (lead < 0xE0) return 2;
    if (lead < 0xF0) return 3;
    return 4;
}

std::uint32_t code_point(std::string_view text, std::size_t at, std::size_t length) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
    switch (length) {
        case 2: return (byte(0) & 0x1Fu) << 6 | (byte(1) & 0x3Fu);
        case 3: return (byte(0) & 0x0Fu) << 12 | (byte(1) & 0x3Fu) << 6 | (byte(2) & 0x3Fu);
        case 4: return (byte(0) & 0x07u) << 18 | (byte(1) & 0x3Fu) << 12 | (byte(2) & 0x3Fu) << 6 | (byte(3) & 0x3Fu);
        default: return byte(0);
    }
}

// East Asian wide ranges (Unicode UAX #11, the blocks ESI texts use).
bool is_wide(std::uint32_t cp) {
    return (cp >= 0x1100 && cp <= 0x115F) || (cp >= 0x2E80 && cp <= 0xA4CF) || (cp >= 0xAC00 && cp <= 0xD7A3) ||
           (cp >= 0xF900 && cp <= 0xFAFF) || (cp >= 0xFE30 && cp <= 0xFE4F) || (cp >= 0xFF00 && cp <= 0xFF60) ||
           (cp >= 0xFFE0 && cp <= 0xFFE6) || (cp >= 0x20000 && cp <= 0x3FFFD);
}

struct Walk {
    std::size_t bytes = 0;
    std::size_t columns = 0;
};

// Walks whole code points while they fit in `limit` columns.
Walk walk(std::string_view text, std::size_t limit) {
    Walk w;
    while (w.bytes < text.size()) {
        const std::size_t length = std::min(sequence_length(static_cast<unsigned char>(text[w.bytes])), text.size() - w.bytes);
        const std::size_t width = is_wide(code_point(text, w.bytes, length)) ? 2 : 1;
        if (w.columns + width > limit) break;
        w.columns += width;
        w.bytes += length;
    }
    return w;
}

}  // namespace

std::size_t display_columns(std::string_view text) { return walk(text, static_cast<std::size_t>(-1)).columns; }

std::string shortened(std::string_view text, std::size_t columns) {
    if (walk(text, columns).bytes == text.size()) return std::string(text);
    if (columns < 2) return {};
    const Walk head = walk(text, columns - 1);
    std::string out(text.substr(0, head.bytes));
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "…";
}

std::string slug(std::string_view text, std::string_view fallback) {
    std::string out;
    bool gap = false;
    for (char c : text) {
        const bool keep = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
        if (!keep) {
            gap = true;
            continue;
        }
        if (gap && !out.empty()) out += '-';
        gap = false;
        out += c;
    }
    while (!out.empty() && (out.back() == '-' || out.back() == '.')) out.pop_back();
    while (!out.empty() && (out.front() == '-' || out.front() == '.')) out.erase(out.begin());
    return out.empty() ? std::string(fallback) : out;
}

}  // namespace esi::doc
