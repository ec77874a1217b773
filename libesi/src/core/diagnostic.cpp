#include "esi/diagnostic.hpp"

#include <algorithm>
#include <tuple>

namespace esi {

std::string_view to_string(Severity severity) {
    switch (severity) {
        case Severity::info: return "info";
        case Severity::warning: return "warning";
        case Severity::error: return "error";
    }
    return "error";
}

bool parse_severity(std::string_view text, Severity& out) {
    if (text == "info") out = Severity::info;
    else if (text == "warning") out = Severity::warning;
    else if (text == "error") out = Severity::error;
    else return false;
    return true;
}

Diagnostic& Diagnostics::emplace(Severity severity, std::string rule, std::string message, std::string path, SourcePos pos) {
    items_.push_back(Diagnostic{severity, std::move(rule), std::move(message), std::move(path), pos, {}});
    return items_.back();
}

void Diagnostics::append(Diagnostics&& other) {
    if (items_.empty()) {
        items_ = std::move(other.items_);
        return;
    }
    items_.insert(items_.end(), std::make_move_iterator(other.items_.begin()), std::make_move_iterator(other.items_.end()));
}

bool Diagnostics::has_errors() const {
    return std::any_of(items_.begin(), items_.end(), [](const Diagnostic& d) { return d.severity == Severity::error; });
}

std::size_t Diagnostics::count(Severity severity) const {
    return static_cast<std::size_t>(
        std::count_if(items_.begin(), items_.end(), [severity](const Diagnostic& d) { return d.severity == severity; }));
}

void Diagnostics::sort() {
    std::stable_sort(items_.begin(), items_.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return std::tie(a.path, a.pos.line, a.pos.column, a.rule, a.message) <
               std::tie(b.path, b.pos.line, b.pos.column, b.rule, b.message);
    });
}

}  // namespace esi
