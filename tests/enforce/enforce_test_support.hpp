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

// The STÖBER sample, which declares its manual's limits, broken in the four ways of issue 11.
// Each edit is found by its text, so that the sample may change around it.
inline void edit(std::string& text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "the sample no longer contains: " << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
}

inline const std::string fifth_rx_pdo = "      - { index: 0x1604, name: PDO5 rx, assigned: false, entries: [] }\n";

inline std::string stoeber_with_a_fifth_rx_pdo() {
    std::string text = stoeber_sample();
    const std::string fourth = "      - { index: 0x1603, name: PDO4 rx (A228), assigned: false, entries: [] }\n";
    edit(text, fourth, fourth + fifth_rx_pdo);
    return text;
}

inline std::string stoeber_with_seven_entries() {
    std::string text = stoeber_sample();
    edit(text, "entries: [0x20B4, 0x26E6, 0x24E6]", "entries: [0x20B4, 0x26E6, 0x24E6, 0x20B4, 0x26E6, 0x24E6, 0x20B4]");
    return text;
}

// IB (Init to Bootstrap): the inverter has no bootstrap state.
inline std::string stoeber_with_an_init_cmd_at_ib() {
    std::string text = stoeber_sample();
    const std::string limits = "    # The limits of samples/profiles/inverter-stoeber.yaml";
    edit(text, limits, "    init:\n      - { transition: IB, object: 0x2104, value: 1 }\n\n" + limits);
    return text;
}

// A180 belongs at 0x2000 + 0 × 0x200 + 180 = 0x20B4 (STÖBER manual §7.2.4); here it is at 0x20B5.
inline std::string stoeber_with_a180_at_20b5() {
    std::string text = stoeber_sample();
    edit(text, "0x20B4:\n        name: A180", "0x20B5:\n        name: A180");
    edit(text, "[0x20B4, ", "[0x20B5, ");
    return text;
}

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
