// The text report of esi-diff: a summary line, then one block per device (most severe first), one
// change per line with its class, model path, message and kind, and the positions in both files
// on the next line in the file:line:column form editors jump to.

#include <fmt/format.h>

#include "esi/diff/classification.hpp"
#include "esi/diff/device_groups.hpp"
#include "esi/diff/report.hpp"

namespace esi {

namespace {

std::string location(const std::string& path, SourcePos pos) {
    if (!pos.known()) return path;
    return fmt::format("{}:{}:{}", path, pos.line, pos.column);
}

// A change is one line: line breaks inside names or unmodelled text become spaces.
std::string one_line(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    return out;
}

}  // namespace

std::string render_diff_text(const DiffResult& result, const DiffLabels& labels) {
    std::string out = fmt::format("{} -> {}: {}", labels.old_path, labels.new_path, to_string(result.verdict));
    if (result.identical()) return out + " (no changes)\n";
    out += fmt::format(" ({}", class_counts(result));
    if (const std::size_t errors = result.error_count()) out += fmt::format("; {} error{}", errors, errors == 1 ? "" : "s");
    out += ")\n";

    for (const auto& group : group_by_device(result)) {
        out += fmt::format("\n{}{}: {}\n", group.device->has_value() ? "Device " : "", one_line(device_heading(*group.device)),
                           group.has_error ? "error" : to_string(group.worst));
        for (const Change* c : group.changes) {
            const std::string_view label = is_error(c->kind) ? std::string_view("error") : to_string(c->change_class);
            out += fmt::format("  {:<10}  {}: {} [{}]\n", label, c->path.empty() ? "." : one_line(c->path), one_line(c->message),
                               to_string(c->kind));
            out += fmt::format("  {:<10}  {} -> {}\n", "", location(labels.old_path, c->old_pos),
                               location(labels.new_path, c->new_pos));
        }
    }
    return out;
}

}  // namespace esi
