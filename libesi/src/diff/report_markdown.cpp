// The Markdown report of esi-diff, for a pull-request comment: the verdict, a warning when a breaking
// change came without a RevisionNo change, then a table per device (most severe first) with the
// cosmetic changes folded away. Long reports are cut so the comment stays postable (GitHub
// rejects comments over 65536 characters).

#include <fmt/format.h>

#include "esi/diff/classification.hpp"
#include "esi/diff/device_groups.hpp"
#include "esi/diff/report.hpp"

namespace esi {

namespace {

constexpr std::size_t max_rows = 300;

// Text inside a table cell: no pipes, no line breaks, no backticks (they would end a code
// span). Outside a code span `<` and `>` are escaped too, or GitHub would read them as HTML; inside
// one they show as written.
std::string table_text(std::string_view s, bool inside_code_span) {
    std::string out;
    for (char c : s) {
        if (c == '|')
            out += "\\|";
        else if (c == '\n' || c == '\r')
            out += ' ';
        else if (c == '`')
            out += '\'';
        else if (c == '<' && !inside_code_span)
            out += "&lt;";
        else if (c == '>' && !inside_code_span)
            out += "&gt;";
        else
            out += c;
    }
    return out;
}

std::string cell(std::string_view s) { return table_text(s, false); }

std::string code(std::string_view s) { return "`" + table_text(s, true) + "`"; }

std::string lines(const Change& c) {
    auto line = [](SourcePos p) { return p.known() ? std::to_string(p.line) : std::string("-"); };
    return fmt::format("{} → {}", line(c.old_pos), line(c.new_pos));
}

std::string row(const Change& c) {
    const std::string label = is_error(c.kind)                          ? "**error**"
                              : c.change_class == ChangeClass::breaking ? "**breaking**"
                                                                        : std::string(to_string(c.change_class));
    return fmt::format("| {} | {} | {} | {} |\n", label, code(c.path.empty() ? "." : c.path), cell(c.message), lines(c));
}

const char* table_head = "| Class | Path | Change | Line (old → new) |\n|---|---|---|---|\n";

}  // namespace

std::string render_diff_markdown(const DiffResult& result, const DiffLabels& labels) {
    std::string out = fmt::format("### esi-diff: {}\n\n", to_string(result.verdict));
    out += fmt::format("{} → {}: {}.\n", code(labels.old_path), code(labels.new_path), class_counts(result));
    if (result.identical()) return out;
    if (const std::size_t errors = result.error_count())
        out += fmt::format(
            "\n> [!CAUTION]\n> {} device{} changed in a breaking way without a new RevisionNo. Masters match devices by "
            "vendor, product code and revision, so configurations made from the old file will accept the changed "
            "device.\n",
            errors, errors == 1 ? "" : "s");

    std::size_t rows = 0;
    std::size_t left_out = 0;
    for (const auto& group : group_by_device(result)) {
        out += fmt::format("\n#### {}{} — {}\n\n", group.device->has_value() ? "Device " : "",
                           cell(device_heading(*group.device)), group.has_error ? "error" : to_string(group.worst));
        std::vector<const Change*> shown;
        std::vector<const Change*> folded;
        for (const Change* c : group.changes) (c->change_class == ChangeClass::cosmetic ? folded : shown).push_back(c);
        if (!shown.empty()) {
            out += table_head;
            for (const Change* c : shown) {
                if (rows++ >= max_rows) {
                    ++left_out;
                    continue;
                }
                out += row(*c);
            }
        }
        if (!folded.empty()) {
            out += fmt::format("{}<details><summary>{} cosmetic change{}</summary>\n\n{}", shown.empty() ? "" : "\n",
                               folded.size(), folded.size() == 1 ? "" : "s", table_head);
            for (const Change* c : folded) {
                if (rows++ >= max_rows) {
                    ++left_out;
                    continue;
                }
                out += row(*c);
            }
            out += "\n</details>\n";
        }
    }
    if (left_out)
        out +=
            fmt::format("\n{} more change{} left out to keep this comment short; run `esi-diff --format text` for all of them.\n",
                        left_out, left_out == 1 ? "" : "s");
    return out;
}

}  // namespace esi
