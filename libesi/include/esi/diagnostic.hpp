#pragma once
// Diagnostics are the library's error channel: every front end, pass and back end returns
// them as values. Nothing in libesi prints or exits.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/source_pos.hpp"

namespace esi {

enum class Severity { info, warning, error };

[[nodiscard]] std::string_view to_string(Severity severity);
// Accepts "info", "warning", "error" (case-sensitive); returns false on anything else.
[[nodiscard]] bool parse_severity(std::string_view text, Severity& out);

// Messages quote values from the input, and a hostile file can make a value megabytes long.
// A diagnostic keeps at most this many bytes of a message: its start and its end (which carries
// the explanation), with the number of bytes left out in between (docs/reliability.md).
inline constexpr std::size_t max_message_bytes = 4096;
[[nodiscard]] std::string bounded_message(std::string message);

// A value for quoting in a message: the text itself when it has at most `max_bytes` bytes, else
// its first bytes (cut at a UTF-8 character boundary) followed by "… (N bytes)".
[[nodiscard]] std::string excerpt(std::string_view text, std::size_t max_bytes = 64);

// A secondary location that explains a diagnostic ("first defined here").
struct DiagnosticNote {
    std::string path;
    SourcePos pos;
    std::string message;
};

// A safe fix (ruff's term): the text that makes a finding go away is certain, so a tool may
// apply it unasked (esi-lint --fix, an editor's quick fix). The edits address the file's decoded
// UTF-8 text (esi/source_text.hpp) by byte offset; they do not overlap and come in order.
struct TextEdit {
    std::size_t offset = 0;
    std::size_t length = 0;  // bytes replaced; 0 inserts
    std::string replacement;
};

struct Fix {
    std::string description;  // what the fix does, e.g. "write #x for 0x"
    std::vector<TextEdit> edits;
};

struct Diagnostic {
    Severity severity = Severity::error;
    std::string rule;  // stable kebab-case id, e.g. "sm-direction-swapped"
    std::string message;
    std::string path;  // file the position refers to; may be empty for stdin-less contexts
    SourcePos pos;
    std::vector<DiagnosticNote> notes;
    std::optional<Fix> fix = std::nullopt;  // set by the rule (or front end) when the finding has a safe fix
};

// How every tool prints a diagnostic, in the layout of GCC and Clang that editors and CI log
// parsers recognise:
//   path:line:col: severity: message [rule]
//   path:line:col: note: message              (one line per note)
// Unknown parts of a position are left out; an empty path prints as `path_when_unknown`.
// With `color`, the location is bold and the severity coloured (ANSI), as compilers do on a
// terminal.
struct DiagnosticStyle {
    std::string_view path_when_unknown = "<input>";
    bool color = false;
};

[[nodiscard]] std::string format_location(std::string_view path, SourcePos pos, const DiagnosticStyle& style = {});
// The first line of a diagnostic, with its newline.
[[nodiscard]] std::string format_diagnostic_line(const Diagnostic& diagnostic, const DiagnosticStyle& style = {});
[[nodiscard]] std::string format_note_line(const DiagnosticNote& note, const DiagnosticStyle& style = {});
// The first line and the notes.
[[nodiscard]] std::string format_diagnostic(const Diagnostic& diagnostic, const DiagnosticStyle& style = {});

class Diagnostics {
public:
    void add(Diagnostic diagnostic);
    Diagnostic& emplace(Severity severity, std::string rule, std::string message, std::string path, SourcePos pos);
    void append(const Diagnostics& other) { items_.insert(items_.end(), other.items_.begin(), other.items_.end()); }
    void append(Diagnostics&& other);

    [[nodiscard]] bool has_errors() const;
    [[nodiscard]] std::size_t count(Severity severity) const;
    [[nodiscard]] bool empty() const { return items_.empty(); }
    [[nodiscard]] std::size_t size() const { return items_.size(); }

    [[nodiscard]] const std::vector<Diagnostic>& items() const { return items_; }
    [[nodiscard]] std::vector<Diagnostic>& items() { return items_; }
    [[nodiscard]] auto begin() const { return items_.begin(); }
    [[nodiscard]] auto end() const { return items_.end(); }

    // Orders by path, line, column, rule, message: the order every output format uses,
    // so that parallel runs print byte-identical reports.
    void sort();

private:
    std::vector<Diagnostic> items_;
};

}  // namespace esi
