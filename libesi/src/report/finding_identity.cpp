#include "report/finding_identity.hpp"

#include <fmt/format.h>

namespace esi::report_detail {

namespace fs = std::filesystem;

namespace {

// 64-bit FNV-1a: stable across runs, compilers and machines, unlike std::hash.
std::uint64_t fnv1a(std::string_view text, std::uint64_t hash = 0xcbf29ce484222325ull) {
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 0x100000001b3ull;
    }
    return hash;
}

std::string normalised(std::string_view line) {
    std::string out;
    bool space = false;
    for (char c : line) {
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            space = !out.empty();
            continue;
        }
        if (space) out.push_back(' ');
        space = false;
        out.push_back(c);
    }
    return out;
}

}  // namespace

std::string repository_path(const std::string& path, const fs::path& root) {
    if (path.empty() || path.front() == '<') return path;
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec).lexically_normal();
    const fs::path relative = absolute.lexically_relative(root.lexically_normal());
    if (!root.empty() && !relative.empty() && *relative.begin() != ".." && relative != ".") return relative.generic_string();
    return absolute.generic_string();
}

std::string Fingerprints::next(const Diagnostic& d, const std::string& repository_path,
                               const std::map<std::uint32_t, std::string>& quoted_lines) {
    const auto line = quoted_lines.find(d.pos.line);
    const std::string anchor = d.pos.known() && line != quoted_lines.end() ? normalised(line->second) : d.message;
    const std::uint64_t hash = fnv1a(anchor, fnv1a(repository_path + '\n', fnv1a(d.rule + '\n')));
    const std::string base = fmt::format("{:016x}", hash);
    return fmt::format("{}:{}", base, ++seen_[base]);
}

}  // namespace esi::report_detail
