// The unified diff of --diff, built from the edits rather than by comparing the two texts: only
// the lines an edit touches change, so the hunks are those lines with their context.

#include <algorithm>

#include "esi/lint/fix.hpp"

namespace esi {

namespace {

constexpr std::size_t context_lines = 3;

// Offsets where each line of a text starts (line i: [starts[i], starts[i + 1])).
std::vector<std::size_t> line_starts(std::string_view text) {
    std::vector<std::size_t> starts{0};
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n' && i + 1 < text.size()) starts.push_back(i + 1);
    return starts;
}

std::size_t line_index(const std::vector<std::size_t>& starts, std::size_t offset) {
    return static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), offset) - starts.begin()) - 1;
}

// Splits into lines keeping each terminator; a last line without one is marked for the
// "\ No newline at end of file" line.
std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        const std::size_t newline = text.find('\n');
        const std::size_t length = newline == std::string_view::npos ? text.size() : newline + 1;
        lines.push_back(text.substr(0, length));
        text.remove_prefix(length);
    }
    return lines;
}

void append_line(std::string& out, char mark, std::string_view line) {
    out.push_back(mark);
    out.append(line);
    if (line.empty() || line.back() != '\n') out += "\n\\ No newline at end of file\n";
}

// Lines [first, last] of the original that edits touch, with the edits that fall in them.
struct Span {
    std::size_t first = 0;
    std::size_t last = 0;
    std::vector<const TextEdit*> edits;
};

}  // namespace

std::string unified_diff(std::string_view original, const std::vector<TextEdit>& edits, const std::string& path) {
    if (edits.empty()) return {};
    const std::vector<std::size_t> starts = line_starts(original);
    const std::size_t line_count = original.empty() ? 0 : starts.size();
    auto line_text = [&](std::size_t i) {
        const std::size_t end = i + 1 < starts.size() ? starts[i + 1] : original.size();
        return original.substr(starts[i], end - starts[i]);
    };

    std::vector<Span> spans;
    for (const TextEdit& e : edits) {
        const std::size_t first = line_index(starts, e.offset);
        const std::size_t last = line_index(starts, e.offset + (e.length ? e.length - 1 : 0));
        if (!spans.empty() && first <= spans.back().last) {
            spans.back().last = std::max(spans.back().last, last);
            spans.back().edits.push_back(&e);
        } else {
            spans.push_back({first, last, {&e}});
        }
    }

    std::string out = "--- a/" + path + "\n+++ b/" + path + "\n";
    std::ptrdiff_t shift = 0;  // new line number minus old, before the current hunk
    for (std::size_t s = 0; s < spans.size();) {
        // A hunk: spans whose contexts touch.
        std::size_t t = s;
        while (t + 1 < spans.size() && spans[t + 1].first <= spans[t].last + 2 * context_lines + 1) ++t;
        const std::size_t begin = spans[s].first > context_lines ? spans[s].first - context_lines : 0;
        const std::size_t end = std::min(line_count, spans[t].last + context_lines + 1);  // one past
        std::string body;
        std::size_t old_lines = 0;
        std::size_t new_lines = 0;
        std::size_t line = begin;
        for (std::size_t k = s; k <= t; ++k) {
            for (; line < spans[k].first; ++line, ++old_lines, ++new_lines) append_line(body, ' ', line_text(line));
            const std::size_t from = starts[spans[k].first];
            const std::size_t to = spans[k].last + 1 < starts.size() ? starts[spans[k].last + 1] : original.size();
            std::string replaced;
            std::size_t at = from;
            for (const TextEdit* e : spans[k].edits) {
                replaced.append(original.substr(at, e->offset - at));
                replaced.append(e->replacement);
                at = e->offset + e->length;
            }
            replaced.append(original.substr(at, to - at));
            for (; line <= spans[k].last; ++line, ++old_lines) append_line(body, '-', line_text(line));
            for (std::string_view l : split_lines(replaced)) {
                append_line(body, '+', l);
                ++new_lines;
            }
        }
        for (; line < end; ++line, ++old_lines, ++new_lines) append_line(body, ' ', line_text(line));
        const std::size_t old_start = old_lines ? begin + 1 : begin;
        const auto new_begin = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(begin) + shift);
        const std::size_t new_start = new_lines ? new_begin + 1 : new_begin;
        out += "@@ -" + std::to_string(old_start) + "," + std::to_string(old_lines) + " +" + std::to_string(new_start) + "," +
               std::to_string(new_lines) + " @@\n";
        out += body;
        shift += static_cast<std::ptrdiff_t>(new_lines) - static_cast<std::ptrdiff_t>(old_lines);
        s = t + 1;
    }
    return out;
}

}  // namespace esi
