#include "corpus/verdict_table.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace esi::test {

namespace {

std::vector<std::string> split_tabs(std::string_view line) {
    std::vector<std::string> cols;
    std::size_t start = 0;
    for (;;) {
        const std::size_t tab = line.find('\t', start);
        cols.emplace_back(line.substr(start, tab == std::string_view::npos ? std::string_view::npos : tab - start));
        if (tab == std::string_view::npos) break;
        start = tab + 1;
    }
    return cols;
}

// Calls `row` with the columns of every data line (not the header, not comments).
template <typename Row>
void for_each_row(std::string_view tsv, Row row) {
    bool header = true;
    std::size_t start = 0;
    while (start < tsv.size()) {
        std::size_t end = tsv.find('\n', start);
        if (end == std::string_view::npos) end = tsv.size();
        std::string_view line = tsv.substr(start, end - start);
        start = end + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.empty() || line.front() == '#') continue;
        if (header) {
            header = false;
            continue;
        }
        row(split_tabs(line));
    }
}

std::string pad(std::string text, std::size_t width) {
    if (text.size() < width) text.append(width - text.size(), ' ');
    return text;
}

std::string file_list(const std::vector<std::string>& files) {
    constexpr std::size_t shown = 3;
    std::string out = std::to_string(files.size()) + (files.size() == 1 ? " file: " : " files: ");
    for (std::size_t i = 0; i < files.size() && i < shown; ++i) out += (i ? ", " : "") + files[i];
    if (files.size() > shown) out += ", +" + std::to_string(files.size() - shown) + " more";
    return out;
}

std::size_t total(const VerdictTable& table) {
    std::size_t n = 0;
    for (const auto& [key, count] : table) n += count;
    return n;
}

std::size_t total_errors(const VerdictTable& table) {
    std::size_t n = 0;
    for (const auto& [key, count] : table)
        if (std::get<2>(key) == "error") n += count;
    return n;
}

std::set<std::string> files_of(const VerdictTable& table) {
    std::set<std::string> files;
    for (const auto& [key, count] : table) files.insert(std::get<0>(key));
    return files;
}

}  // namespace

VerdictTable parse_verdicts(std::string_view tsv) {
    VerdictTable table;
    for_each_row(tsv, [&](const std::vector<std::string>& cols) {
        if (cols.size() != 4) throw std::runtime_error("verdict line without 4 columns: " + cols.front());
        table[{cols[0], cols[1], cols[2]}] += std::stoul(cols[3]);
    });
    return table;
}

std::string format_verdicts(const VerdictTable& table) {
    std::string out = "file\trule\tseverity\tcount\n";
    for (const auto& [key, count] : table) {
        const auto& [file, rule, severity] = key;
        out += file + '\t' + rule + '\t' + severity + '\t' + std::to_string(count) + '\n';
    }
    return out;
}

VerdictTable verdicts_from_lint_json(std::string_view json, const std::string& corpus_dir) {
    const auto root = nlohmann::json::parse(json);
    VerdictTable table;
    for (const auto& d : root.at("diagnostics")) {
        const std::filesystem::path path = d.at("path").get<std::string>();
        const std::string file = path.lexically_relative(corpus_dir).generic_string();
        table[{file.empty() ? path.generic_string() : file, d.at("rule").get<std::string>(), d.at("severity").get<std::string>()}] += 1;
    }
    return table;
}

Origins parse_origins(std::string_view tsv) {
    Origins origins;
    for_each_row(tsv, [&](const std::vector<std::string>& cols) {
        if (cols.size() < 2) throw std::runtime_error("origin line without an origin: " + cols.front());
        origins[cols[0]] = cols[1];
    });
    return origins;
}

std::set<std::string> failing_files(const VerdictTable& table) {
    std::set<std::string> failing;
    for (const auto& [key, count] : table)
        if (std::get<2>(key) == "error" && count > 0) failing.insert(std::get<0>(key));
    return failing;
}

OfficialFigures official_figures(const VerdictTable& table, const Origins& origins) {
    auto official = [&](const std::string& file) {
        const auto it = origins.find(file);
        return it != origins.end() && it->second == "official";
    };
    OfficialFigures figures;
    for (const auto& [file, origin] : origins)
        if (origin == "official") ++figures.official_files;
    for (const auto& file : failing_files(table))
        if (official(file)) ++figures.failing;
    for (const auto& [key, count] : table)
        if (std::get<2>(key) == "error" && official(std::get<0>(key))) figures.error_findings += count;
    return figures;
}

std::string describe_change(const VerdictTable& snapshot, const VerdictTable& now, const Origins& origins) {
    const OfficialFigures before = official_figures(snapshot, origins);
    const OfficialFigures after = official_figures(now, origins);
    std::ostringstream out;
    if (snapshot == now) {
        out << "esi-lint corpus verdicts match the snapshot: " << total(now) << " findings (" << total_errors(now)
            << " errors) in " << files_of(now).size() << " files; official vendor files failing --fail-on error: "
            << after.failing << " of " << after.official_files << ", with " << after.error_findings
            << " error findings\n";
        return out.str();
    }

    // Per (rule, severity): findings added and removed, and the files where the count moved.
    struct RuleChange {
        std::size_t before = 0, after = 0, added = 0, removed = 0;
        std::vector<std::string> files;
    };
    std::map<std::pair<std::string, std::string>, RuleChange> rules;
    std::set<VerdictKey> keys;
    for (const auto& [key, count] : snapshot) keys.insert(key);
    for (const auto& [key, count] : now) keys.insert(key);
    std::size_t added = 0, removed = 0;
    for (const auto& key : keys) {
        const auto b = snapshot.count(key) ? snapshot.at(key) : 0;
        const auto a = now.count(key) ? now.at(key) : 0;
        RuleChange& change = rules[{std::get<1>(key), std::get<2>(key)}];
        change.before += b;
        change.after += a;
        if (a == b) continue;
        (a > b ? change.added : change.removed) += a > b ? a - b : b - a;
        (a > b ? added : removed) += a > b ? a - b : b - a;
        change.files.push_back(std::get<0>(key));
    }

    out << "esi-lint corpus verdicts differ from the snapshot: " << total(snapshot) << " -> " << total(now) << " findings (+"
        << added << "/-" << removed << "), errors " << total_errors(snapshot) << " -> " << total_errors(now) << "\n";
    out << "official vendor files failing --fail-on error: " << before.failing << " -> " << after.failing << " of "
        << after.official_files << "; error findings on them: " << before.error_findings << " -> " << after.error_findings
        << "\n\nper rule and severity (findings in the snapshot -> now):\n";
    for (const auto& [id, change] : rules) {
        if (change.files.empty()) continue;
        out << "  " << pad("+" + std::to_string(change.added) + "/-" + std::to_string(change.removed), 12)
            << pad(id.first, 32) << pad(id.second, 9) << pad(std::to_string(change.before) + " -> " + std::to_string(change.after), 14)
            << file_list(change.files) << "\n";
    }

    const std::set<std::string> failed = failing_files(snapshot);
    const std::set<std::string> fails = failing_files(now);
    std::vector<std::pair<std::string, std::string>> flips;  // (direction, file)
    for (const auto& file : failed)
        if (!fails.count(file)) flips.emplace_back("FAIL -> pass", file);
    for (const auto& file : fails)
        if (!failed.count(file)) flips.emplace_back("pass -> FAIL", file);
    out << "\nfiles whose --fail-on error verdict flips: " << (flips.empty() ? "none" : std::to_string(flips.size())) << "\n";
    for (const auto& [direction, file] : flips) {
        const auto origin = origins.find(file);
        out << "  " << direction << "  " << file << "  (" << (origin == origins.end() ? "no origin" : origin->second) << ")\n";
    }
    return out.str();
}

}  // namespace esi::test
