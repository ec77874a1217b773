#include "esi/report/lint_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include <nlohmann/json.hpp>

#include "esi/check/registry.hpp"
#include "esi/check/severity_model.hpp"
#include "report/json_writer.hpp"

namespace esi {

namespace {

using ordered_json = nlohmann::ordered_json;

// Every diagnostic of the report in output order: config problems first, then each file's.
template <class F>
void for_each_diagnostic(const LintReport& report, F&& f) {
    static const std::map<std::uint32_t, std::string> no_lines;
    for (const auto& d : report.config_diagnostics) f(d, no_lines);
    for (const auto& file : report.files)
        for (const auto& d : file.diagnostics) f(d, file.quoted_lines);
}

// The caret line under a quoted source line: keep tabs so the caret lines up.
std::string caret_line(std::string_view line, std::uint32_t column) {
    std::string out;
    std::uint32_t code_point = 1;
    for (std::size_t i = 0; i < line.size() && code_point < column; ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if ((c & 0xC0) == 0x80) continue;
        out.push_back(c == '\t' ? '\t' : ' ');
        ++code_point;
    }
    out.push_back('^');
    return out;
}

// A quoted source line is cut to a window around the column when it is long: a minified file or
// a hostile 50 MB attribute would otherwise be printed whole, twice (line and caret line).
constexpr std::size_t quoted_line_limit = 240;

struct QuotedLine {
    std::string text;
    std::uint32_t column = 0;  // the caret column within `text`
};

QuotedLine quoted_window(std::string_view line, std::uint32_t column) {
    if (line.size() <= quoted_line_limit) return {std::string(line), column};
    auto is_continuation = [&](std::size_t i) { return (static_cast<unsigned char>(line[i]) & 0xC0) == 0x80; };
    // Byte offset of the column (columns count code points).
    std::size_t at = 0;
    for (std::uint32_t cp = 1; at < line.size() && cp < column; ++cp) {
        ++at;
        while (at < line.size() && is_continuation(at)) ++at;
    }
    std::size_t begin = at > quoted_line_limit / 3 ? at - quoted_line_limit / 3 : 0;
    while (begin > 0 && is_continuation(begin)) --begin;
    std::size_t end = std::min(line.size(), begin + quoted_line_limit);
    while (end < line.size() && is_continuation(end)) ++end;
    QuotedLine out;
    out.column = 1;
    if (begin > 0) {
        out.text = "…";
        ++out.column;
    }
    for (std::size_t i = begin; i < at; ++i)
        if (!is_continuation(i)) ++out.column;
    out.text.append(line.substr(begin, end - begin));
    if (end < line.size()) out.text += "…";
    return out;
}

std::size_t skipped_files(const LintReport& report) {
    return static_cast<std::size_t>(
        std::count_if(report.files.begin(), report.files.end(), [](const FileReport& f) { return !f.skipped.empty(); }));
}

std::string summary_line(const LintReport& report) {
    if (report.stopped_by_config) return "no file linted: the configuration has errors (see above)\n";
    const std::size_t errors = report.count(Severity::error);
    const std::size_t warnings = report.count(Severity::warning);
    const std::size_t infos = report.count(Severity::info);
    const std::size_t skipped = skipped_files(report);
    auto plural = [](std::size_t n, std::string_view word) { return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s"); };
    std::string aside;
    if (skipped) aside += fmt::format("{} not ESI, skipped", skipped);
    if (report.excluded) aside += fmt::format("{}{} excluded", aside.empty() ? "" : "; ", report.excluded);
    if (report.baselined) aside += fmt::format("{}{} in the baseline", aside.empty() ? "" : "; ", plural(report.baselined, "finding"));
    return fmt::format("{}, {}, {} in {}{}\n", plural(errors, "error"), plural(warnings, "warning"), plural(infos, "info"),
                       plural(report.files.size() - skipped, "file"), aside.empty() ? "" : " (" + aside + ")");
}

std::string github_escape_data(std::string_view s) {
    std::string out;
    for (char c : s) {
        if (c == '%') out += "%25";
        else if (c == '\r') out += "%0D";
        else if (c == '\n') out += "%0A";
        else out.push_back(c);
    }
    return out;
}

std::string github_escape_property(std::string_view s) {
    std::string out;
    for (char c : github_escape_data(s)) {
        if (c == ':') out += "%3A";
        else if (c == ',') out += "%2C";
        else out.push_back(c);
    }
    return out;
}

}  // namespace

std::string render_text(const LintReport& report, const TextOutputOptions& options) {
    std::string out;
    const DiagnosticStyle style{.path_when_unknown = "", .color = options.color};
    for_each_diagnostic(report, [&](const Diagnostic& d, const std::map<std::uint32_t, std::string>& lines) {
        out += format_diagnostic_line(d, style);
        if (options.show_source && d.pos.known()) {
            const auto it = lines.find(d.pos.line);
            const std::string_view line = it == lines.end() ? std::string_view{} : std::string_view(it->second);
            if (!line.empty()) {
                const QuotedLine quoted = quoted_window(line, d.pos.column);
                out += fmt::format("{:>6} | {}\n", d.pos.line, quoted.text);
                out += fmt::format("{:>6} | {}\n", "", caret_line(quoted.text, quoted.column));
            }
        }
        for (const auto& note : d.notes) out += format_note_line(note, style);
    });
    for (const auto& file : report.files)
        if (!file.skipped.empty())
            out += format_note_line(DiagnosticNote{file.path, {}, "skipped: " + file.skipped}, style);
    out += summary_line(report);
    return out;
}

// Written straight into the output (report/json_writer.hpp), in the layout nlohmann's dump(2) gave
// it before; a corpus-wide run reports thousands of findings.
std::string render_json(const LintReport& report) {
    report::JsonWriter json;
    json.begin_object();
    json.key("diagnostics");
    json.begin_array();
    for_each_diagnostic(report, [&](const Diagnostic& d, const std::map<std::uint32_t, std::string>&) {
        json.begin_object();
        json.member("path", d.path);
        json.member("line", std::uint64_t{d.pos.line});
        json.member("column", std::uint64_t{d.pos.column});
        json.member("severity", to_string(d.severity));
        json.member("rule", d.rule);
        json.member("message", d.message);
        if (!d.notes.empty()) {
            json.key("notes");
            json.begin_array();
            for (const auto& n : d.notes) {
                json.begin_object();
                json.member("path", n.path);
                json.member("line", std::uint64_t{n.pos.line});
                json.member("column", std::uint64_t{n.pos.column});
                json.member("message", n.message);
                json.end_object();
            }
            json.end_array();
        }
        if (d.fix) {
            // Offsets into the file's decoded UTF-8 text, for an editor to apply (esi-lint --fix maps them to the bytes).
            json.key("fix");
            json.begin_object();
            json.member("description", d.fix->description);
            json.key("edits");
            json.begin_array();
            for (const auto& e : d.fix->edits) {
                json.begin_object();
                json.member("offset", std::uint64_t{e.offset});
                json.member("length", std::uint64_t{e.length});
                json.member("replacement", e.replacement);
                json.end_object();
            }
            json.end_array();
            json.end_object();
        }
        json.end_object();
    });
    json.end_array();
    json.key("skipped");
    json.begin_array();
    for (const auto& file : report.files) {
        if (file.skipped.empty()) continue;
        json.begin_object();
        json.member("path", file.path);
        json.member("reason", file.skipped);
        json.end_object();
    }
    json.end_array();
    json.key("summary");
    json.begin_object();
    json.member("files", std::uint64_t{report.files.size() - skipped_files(report)});
    json.member("errors", std::uint64_t{report.count(Severity::error)});
    json.member("warnings", std::uint64_t{report.count(Severity::warning)});
    json.member("infos", std::uint64_t{report.count(Severity::info)});
    json.end_object();
    json.end_object();
    return json.take() + "\n";
}

std::string render_github(const LintReport& report) {
    std::string out;
    for_each_diagnostic(report, [&](const Diagnostic& d, const std::map<std::uint32_t, std::string>&) {
        const std::string_view command = d.severity == Severity::error ? "error" : d.severity == Severity::warning ? "warning" : "notice";
        std::string properties = "file=" + github_escape_property(d.path);
        if (d.pos.known()) properties += fmt::format(",line={},col={}", d.pos.line, d.pos.column);
        properties += ",title=" + github_escape_property(d.rule);
        out += fmt::format("::{} {}::{}\n", command, properties, github_escape_data(d.message));
    });
    return out;
}

std::string render_rule_list_text() {
    std::string out;
    std::size_t width = 0;
    for (const Rule& r : all_rules()) width = std::max(width, r.id.size());
    // Rules whose findings --fix can fix are marked [*], as ruff marks them.
    for (const Rule& r : all_rules())
        out += fmt::format("{:<{}}  {:<7}  {}{}\n", r.id, width, to_string(r.default_severity), r.fix.empty() ? "" : "[*] ", r.summary);
    return out;
}

std::string render_rule_list_json() {
    ordered_json rules = ordered_json::array();
    for (const Rule& r : all_rules())
        rules.push_back({{"id", r.id},
                         {"severity", to_string(r.default_severity)},
                         {"summary", r.summary},
                         {"rationale", r.rationale},
                         {"bad_example", r.bad_example},
                         {"good_example", r.good_example},
                         {"fix", r.fix.empty() ? ordered_json() : ordered_json(r.fix)}});
    return ordered_json{{"rules", std::move(rules)}}.dump(2) + "\n";
}

std::string render_rule_list_markdown() {
    std::string out =
        "# esi-lint rules\n\n"
        "Generated from the rule catalogue (`esi-lint --list-rules --format markdown`); a test keeps this file in sync.\n"
        "Every rule can be switched off or re-graded in `.esi-lint.yaml` (see lint-config.md) and suppressed inline with\n"
        "`<!-- esi-lint: disable=RULE -->`.\n\n"
        "## Severities\n\n" +
        std::string(severity_model) +
        "\n## Catalogue\n\n"
        "| Rule | Default | Summary |\n|---|---|---|\n";
    for (const Rule& r : all_rules()) out += fmt::format("| [`{}`](#{}) | {} | {} |\n", r.id, r.id, to_string(r.default_severity), r.summary);
    for (const Rule& r : all_rules()) {
        out += fmt::format("\n## {}\n\n**{}** (default severity: {})\n\n{}\n\nBad:\n\n```xml\n{}\n```\n\nGood:\n\n```xml\n{}\n```\n",
                           r.id, r.summary, to_string(r.default_severity), r.rationale, r.bad_example, r.good_example);
    }
    return out;
}

std::string render_rule_explanation(std::string_view rule_id) {
    const Rule* r = find_rule(rule_id);
    if (!r) return {};
    std::string out = fmt::format("{} ({})\n{}\n\n{}\n\nBad:\n  {}\n\nGood:\n  {}\n", r->id, to_string(r->default_severity), r->summary,
                                  r->rationale, r->bad_example, r->good_example);
    if (!r->fix.empty()) out += fmt::format("\nFix (--fix): {}\n", r->fix);
    return out;
}

}  // namespace esi
