#pragma once
// Helpers of the limits-enforcement tests: loading a source from text, checking it, and where the
// findings of one rule are.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>

#include "esi/enforce/limits.hpp"
#include "esi/load/document.hpp"
#include "support/test_support.hpp"

namespace esi::test::enforce {

using Where = std::pair<std::uint32_t, std::uint32_t>;  // line, column

inline std::string stoeber_sample() { return read_text(source_dir() / "samples" / "inverter-stoeber-mds5000.yaml"); }

// Loads `text` as the file `path` (it must load without errors) and enforces its limits.
inline Diagnostics check(const std::string& text, const std::string& path = "device.yaml",
                         const std::optional<std::filesystem::path>& config = std::nullopt,
                         const std::optional<DeviceSelector>& device = std::nullopt) {
    const LoadedDocument loaded = load_document(text, path);
    EXPECT_TRUE(loaded.usable()) << (loaded.diagnostics.empty() ? "" : loaded.diagnostics.items()[0].message);
    return enforce_limits(loaded, LimitsOptions{config, device});
}

inline std::set<Where> findings(const Diagnostics& diagnostics, const std::string& rule) {
    std::set<Where> out;
    for (const auto& d : diagnostics)
        if (d.rule == rule) out.emplace(d.pos.line, d.pos.column);
    return out;
}

// The 1-based line of the first occurrence of `needle`; 0 when absent.
inline std::uint32_t line_of(const std::string& text, const std::string& needle) {
    const auto at = text.find(needle);
    if (at == std::string::npos) return 0;
    std::uint32_t line = 1;
    for (std::size_t i = 0; i < at; ++i)
        if (text[i] == '\n') ++line;
    return line;
}

inline std::string describe(const Diagnostics& diagnostics) {
    std::string out;
    for (const auto& d : diagnostics)
        out += d.path + ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + d.rule + ": " + d.message + "\n";
    return out;
}

}  // namespace esi::test::enforce
