#pragma once
// Diagnostics are the library's error channel: every front end, pass and back end returns
// them as values. Nothing in libesi prints or exits.

#include <string>
#include <string_view>
#include <vector>

#include "esi/source_pos.hpp"

namespace esi {

enum class Severity { info, warning, error };

[[nodiscard]] std::string_view to_string(Severity severity);
// Accepts "info", "warning", "error" (case-sensitive); returns false on anything else.
[[nodiscard]] bool parse_severity(std::string_view text, Severity& out);

// A secondary location that explains a diagnostic ("first defined here").
struct DiagnosticNote {
    std::string path;
    SourcePos pos;
    std::string message;
};

struct Diagnostic {
    Severity severity = Severity::error;
    std::string rule;  // stable kebab-case id, e.g. "sm-direction-swapped"
    std::string message;
    std::string path;  // file the position refers to; may be empty for stdin-less contexts
    SourcePos pos;
    std::vector<DiagnosticNote> notes;
};

class Diagnostics {
public:
    void add(Diagnostic diagnostic) { items_.push_back(std::move(diagnostic)); }
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
