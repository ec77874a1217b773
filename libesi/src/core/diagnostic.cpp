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

std::string format_location(std::string_view path, SourcePos pos, const DiagnosticStyle& style) {
    std::string out(path.empty() ? style.path_when_unknown : path);
    if (pos.line) {
        out += ':' + std::to_string(pos.line);
        if (pos.column) out += ':' + std::to_string(pos.column);
    }
    return out;
}

namespace {

constexpr std::string_view bold = "\x1b[1m";
constexpr std::string_view reset = "\x1b[0m";

std::string_view color_of(Severity severity) {
    switch (severity) {
        case Severity::error: return "\x1b[1;31m";
        case Severity::warning: return "\x1b[1;35m";
        case Severity::info: return "\x1b[1;36m";
    }
    return "";
}

// `location: label: message`, the location bold and the label in `label_color` when colouring.
std::string styled_line(std::string_view location, std::string_view label, std::string_view label_color, std::string_view message,
                        const DiagnosticStyle& style) {
    std::string out;
    out.reserve(location.size() + label.size() + message.size() + 32);
    if (style.color) out += bold;
    out += location;
    if (style.color) out += reset;
    out += ": ";
    if (style.color) out += label_color;
    out += label;
    if (style.color) out += reset;
    out += ": ";
    out += message;
    return out;
}

}  // namespace

std::string format_diagnostic_line(const Diagnostic& d, const DiagnosticStyle& style) {
    std::string out = styled_line(format_location(d.path, d.pos, style), to_string(d.severity), color_of(d.severity), d.message, style);
    out += " [";
    out += d.rule;
    out += "]\n";
    return out;
}

std::string format_note_line(const DiagnosticNote& note, const DiagnosticStyle& style) {
    return styled_line(format_location(note.path, note.pos, style), "note", bold, note.message, style) + "\n";
}

std::string format_diagnostic(const Diagnostic& d, const DiagnosticStyle& style) {
    std::string out = format_diagnostic_line(d, style);
    for (const auto& note : d.notes) out += format_note_line(note, style);
    return out;
}

namespace {

// The largest length <= n that does not split a UTF-8 sequence of `text`.
std::size_t character_boundary(std::string_view text, std::size_t n) {
    if (n >= text.size()) return text.size();
    while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;
    return n;
}

}  // namespace

std::string bounded_message(std::string message) {
    if (message.size() <= max_message_bytes) return message;
    // Keep three quarters from the start and the rest from the end, both cut at characters.
    const std::size_t head = character_boundary(message, max_message_bytes * 3 / 4);
    std::size_t tail_start = message.size() - max_message_bytes / 4;
    while (tail_start < message.size() && (static_cast<unsigned char>(message[tail_start]) & 0xC0) == 0x80) ++tail_start;
    const std::size_t left_out = tail_start - head;
    std::string out = message.substr(0, head);
    out += " […";
    out += std::to_string(left_out);
    out += " bytes left out…] ";
    out.append(message, tail_start, std::string::npos);
    return out;
}

std::string excerpt(std::string_view text, std::size_t max_bytes) {
    if (text.size() <= max_bytes) return std::string(text);
    std::string out(text.substr(0, character_boundary(text, max_bytes)));
    out += "… (";
    out += std::to_string(text.size());
    out += " bytes)";
    return out;
}

void Diagnostics::add(Diagnostic diagnostic) {
    diagnostic.message = bounded_message(std::move(diagnostic.message));
    for (auto& note : diagnostic.notes) note.message = bounded_message(std::move(note.message));
    items_.push_back(std::move(diagnostic));
}

Diagnostic& Diagnostics::emplace(Severity severity, std::string rule, std::string message, std::string path, SourcePos pos) {
    items_.push_back(Diagnostic{severity, std::move(rule), bounded_message(std::move(message)), std::move(path), pos, {}, {}});
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
