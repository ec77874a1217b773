#include "esi/lsp/code_actions.hpp"

#include <algorithm>
#include <cctype>

#include "esi/check/registry.hpp"

namespace esi::lsp {

namespace {

using nlohmann::json;

json to_json(Position position) { return {{"line", position.line}, {"character", position.character}}; }
json to_json(Range range) { return {{"start", to_json(range.start)}, {"end", to_json(range.end)}}; }

int lsp_severity(Severity severity) {
    switch (severity) {
        case Severity::error: return 1;
        case Severity::warning: return 2;
        case Severity::info: return 3;
    }
    return 1;
}

bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '.' || c == '-' || c == '#' ||
           (static_cast<unsigned char>(c) >= 0x80);
}

// The byte range a finding underlines: its fix's edit when the fix replaces text there, else the
// name or value starting at its position (an element's name after '<'), at least one character.
std::pair<std::size_t, std::size_t> underline(const Diagnostic& d, std::size_t start, std::string_view text) {
    if (d.fix && d.fix->edits.size() == 1 && d.fix->edits.front().length > 0) {
        const TextEdit& edit = d.fix->edits.front();
        if (edit.offset + edit.length <= text.size()) return {edit.offset, edit.offset + edit.length};
    }
    std::size_t end = start;
    if (end < text.size() && text[end] == '<') ++end;
    while (end < text.size() && name_char(text[end])) ++end;
    if (end == start && end < text.size() && text[end] != '\n' && text[end] != '\r') {
        ++end;
        while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) ++end;
    }
    return {start, end};
}

std::size_t line_start_offset(std::string_view text, std::uint32_t line) {
    std::size_t at = 0;
    for (std::uint32_t i = 1; i < line; ++i) {
        const std::size_t newline = text.find('\n', at);
        if (newline == std::string_view::npos) return text.size();
        at = newline + 1;
    }
    return at;
}

std::string indentation_at(std::string_view text, std::size_t line_start) {
    std::size_t end = line_start;
    while (end < text.size() && (text[end] == ' ' || text[end] == '\t')) ++end;
    return std::string(text.substr(line_start, end - line_start));
}

bool ranges_meet(Range a, Range b) { return !(a.end < b.start) && !(b.end < a.start); }

json workspace_edit(const std::string& uri, const std::vector<TextEdit>& edits, const LineIndex& index) {
    json changes = json::array();
    for (const TextEdit& edit : edits)
        changes.push_back({{"range", to_json(Range{index.position_of(edit.offset), index.position_of(edit.offset + edit.length)})},
                           {"newText", edit.replacement}});
    return {{"changes", {{uri, std::move(changes)}}}};
}

}  // namespace

json to_lsp_diagnostic(const Diagnostic& d, const LineIndex& index, std::string_view text, const std::string& uri) {
    const auto [from, to] = underline(d, index.offset_of(d.pos), text);
    const Position start = index.position_of(from);
    // The end from the start: a finding on a line of a megabyte is counted from its line start once.
    const std::string_view underlined = text.substr(from, to - from);
    const Position end = underlined.find('\n') == std::string_view::npos
                             ? Position{start.line, start.character + static_cast<std::uint32_t>(utf16_length(underlined))}
                             : index.position_of(to);
    json out = {
        {"range", to_json(Range{start, end})},
        {"severity", lsp_severity(d.severity)},
        {"source", "esi-lint"},
        {"message", d.message},
    };
    if (!d.rule.empty()) {
        out["code"] = d.rule;
        // The rules are documented by the tool itself, not on a web page.
        out["data"] = {{"explain", "esi-lint --explain " + d.rule}};
    }
    json related = json::array();
    for (const DiagnosticNote& note : d.notes) {
        if (note.path != d.path || !note.pos.known()) continue;  // another file: no URI to give
        const Position at = index.position_of(note.pos);
        related.push_back({{"location", {{"uri", uri}, {"range", to_json(Range{at, at})}}}, {"message", note.message}});
    }
    if (!related.empty()) out["relatedInformation"] = std::move(related);
    return out;
}

json publish_params(const LintResult& result) {
    const std::string_view text = *result.text;
    const LineIndex index(text);
    json diagnostics = json::array();
    for (const Diagnostic& d : result.lint.report.diagnostics) diagnostics.push_back(to_lsp_diagnostic(d, index, text, result.uri));
    return {{"uri", result.uri}, {"version", result.version}, {"diagnostics", std::move(diagnostics)}};
}

std::vector<TextEdit> suppression_edits(std::string_view text, std::uint32_t line, const std::string& rule) {
    const std::size_t start = line_start_offset(text, line);
    // Inside a tag when the nearest markup delimiter before the line is a '<'.
    const std::size_t delimiter = start == 0 ? std::string_view::npos : text.find_last_of("<>", start - 1);
    if (delimiter == std::string_view::npos || text[delimiter] == '>') {
        return {TextEdit{start, 0, indentation_at(text, start) + "<!-- esi-lint: disable-next-line=" + rule + " -->\n"}};
    }
    const std::size_t tag_line_start = text.rfind('\n', delimiter) == std::string_view::npos ? 0 : text.rfind('\n', delimiter) + 1;
    const std::size_t tag_end = text.find('>', start);
    if (tag_end == std::string_view::npos) return {};  // an unterminated tag: nothing safe to add
    const std::string indent = indentation_at(text, tag_line_start);
    return {TextEdit{tag_line_start, 0, indent + "<!-- esi-lint: disable=" + rule + " -->\n"},
            TextEdit{tag_end + 1, 0, "\n" + indent + "<!-- esi-lint: enable=" + rule + " -->"}};
}

json code_actions(const LintResult& result, Range range) {
    const std::string_view text = *result.text;
    const LineIndex index(text);
    json actions = json::array();
    for (const Diagnostic& d : result.lint.report.diagnostics) {
        json diagnostic = to_lsp_diagnostic(d, index, text, result.uri);
        const Range at{{diagnostic["range"]["start"]["line"], diagnostic["range"]["start"]["character"]},
                       {diagnostic["range"]["end"]["line"], diagnostic["range"]["end"]["character"]}};
        if (!ranges_meet(at, range)) continue;
        if (d.fix && result.lint.fixes_apply && !d.fix->edits.empty() &&
            std::all_of(d.fix->edits.begin(), d.fix->edits.end(),
                        [&](const TextEdit& e) { return e.offset + e.length <= text.size(); })) {
            actions.push_back({{"title", d.fix->description + " (" + d.rule + ")"},
                               {"kind", "quickfix"},
                               {"diagnostics", json::array({diagnostic})},
                               {"isPreferred", true},
                               {"edit", workspace_edit(result.uri, d.fix->edits, index)}});
        }
        // xml-syntax cannot be suppressed; YAML sources have no suppression comments.
        if (result.lint.xml && d.rule != "xml-syntax" && find_rule(d.rule) && d.pos.known()) {
            const std::vector<TextEdit> edits = suppression_edits(text, d.pos.line, d.rule);
            if (!edits.empty())
                actions.push_back({{"title", "Suppress " + d.rule + " here (esi-lint comment)"},
                                   {"kind", "quickfix"},
                                   {"diagnostics", json::array({diagnostic})},
                                   {"edit", workspace_edit(result.uri, edits, index)}});
        }
    }
    return actions;
}

}  // namespace esi::lsp
