// Hostile YAML device sources through esi-gen (issue 6 §2). tests/yaml/bad_input_test.cpp checks
// the library's diagnostics for these cases (alias bombs, nesting, tabs, non-UTF-8, duplicate keys,
// the size limit); here each goes through the tool a firmware build runs: exit code 2, a located
// diagnostic, a short error output, bounded memory (peak RSS of the child; bounds in
// docs/reliability.md) and an output directory left exactly as it was.

#include <gtest/gtest.h>

#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::memory_scale;
using esi::test::run_child;

// A valid device source; cases replace parts of it or add to it.
const std::string header = R"(vendor: { id: 0x10, name: Example }
groups: [{ type: G, name: Group }]
devices:
  - type: D
    name: Device
    product_code: 1
    revision: 2
    mailbox: { size: 128, coe: true }
)";

std::string billion_laughs() {
    // Ten lists of ten aliases to the previous one: 10^9 nodes once expanded.
    std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
    for (int i = 1; i < 10; ++i) {
        text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
        for (int k = 0; k < 10; ++k) text += (k ? ", *a" : "*a") + std::to_string(i - 1);
        text += "]\n";
    }
    return text + header;
}

struct YamlCase {
    const char* name;
    std::string text;
    const char* rule;      // the diagnostic esi-gen prints
    const char* position;  // "device.yaml:LINE:COL" of that diagnostic, or "device.yaml" when the whole file is meant
    long rss_bound_mb;     // peak RSS bound of esi-gen (plain build)
};

std::vector<YamlCase> cases() {
    std::string deep_flow = "vendor: ";
    for (int i = 0; i < 100'000; ++i) deep_flow += "{a: ";
    deep_flow += "1" + std::string(100'000, '}') + "\n";
    std::string deep_block = header;  // 1,000 levels of block mappings (indentation grows by 2 per level)
    for (int i = 0; i < 1'000; ++i) deep_block += std::string(4 + 2 * static_cast<std::size_t>(i), ' ') + "k" + std::to_string(i) + ":\n";
    std::string huge_scalar = header;  // a 12 MB scalar where a number belongs (below the 16 MiB file limit)
    huge_scalar.replace(huge_scalar.find("product_code: 1"), 15, "product_code: \"" + std::string(12 << 20, '7') + "\"");
    // An explicit key ("? …": a simple key is limited to 1,024 characters) of 12 MB: did-you-mean
    // must not compare it with every known key character by character.
    std::string huge_key = header + "    ? " + std::string(12 << 20, 'k') + "\n    : 1\n";
    std::string too_large = header + "    comment: \"" + std::string(17 << 20, 'x') + "\"\n";
    return {
        {"alias bomb", billion_laughs(), "yaml-alias-expansion", "device.yaml:6:45", 64},
        {"100,000 nested flow mappings", deep_flow, "yaml-nesting-depth", "device.yaml:1:261", 64},
        {"1,000 nested block mappings", deep_block, "yaml-nesting-depth", "device.yaml:71:129", 64},
        {"12 MB scalar as a number", huge_scalar, "yaml-number-range", "device.yaml:6:19", 256},
        {"12 MB unknown key", huge_key, "yaml-unknown-key", "device.yaml:9:7", 256},
        {"17 MB file", too_large, "yaml-too-large", "device.yaml", 128},
        {"duplicate key", header + "    name: Again\n", "yaml-duplicate-key", "device.yaml:9:5", 64},
        {"tab indentation", esi::test::replace_once(header, "    name: Device", "\tname: Device"), "yaml-syntax", "device.yaml:5:1", 64},
        {"invalid UTF-8", esi::test::replace_once(header, "name: Example", "name: \"Ex\xC3\x28mple\""), "yaml-syntax", "device.yaml:1:", 64},
        {"UTF-16 lone surrogate", std::string("\xFF\xFE\x00\xD8v\x00", 6), "yaml-syntax", "device.yaml:1:3", 64},  // its NUL bytes: not a YAML text
        {"NUL byte", esi::test::replace_once(header, "Example", std::string("Exa\0mple", 8)), "yaml-syntax", "device.yaml:1:30", 64},
    };
}

}  // namespace

TEST(HostileYaml, EsiGenRefusesEveryCaseAndWritesNothing) {
    for (const auto& c : cases()) {
        SCOPED_TRACE(c.name);
        esi::test::TempDir dir;
        esi::test::write_text(dir / "device.yaml", c.text);
        esi::test::write_text(dir / "out" / "device.h", "previous output\n");
        const auto before = esi::test::snapshot(dir / "out");
        const auto gen = run_child({esi::test::tool("esi-gen").string(), (dir / "device.yaml").string(), "-o", (dir / "out").string()});
        EXPECT_EQ(gen.exit_code, 2) << gen.err;
        EXPECT_NE(gen.err.find(c.rule), std::string::npos) << gen.err.substr(0, 2000);
        EXPECT_NE(gen.err.find(c.position), std::string::npos) << gen.err.substr(0, 2000);
        // Messages quote hostile text in short excerpts: the error output stays small.
        EXPECT_LT(gen.err.size(), 16u * 1024u);
        EXPECT_LT(gen.max_rss_kb, c.rss_bound_mb * 1024 * memory_scale()) << "peak RSS " << gen.max_rss_kb << " kB";
        EXPECT_TRUE(esi::test::snapshot(dir / "out") == before) << "the output directory changed";
    }
}

TEST(HostileYaml, AnEndlessYamlStreamIsCutAtTheSourceLimit) {
    // A device source path that is a character device: read in chunks, cut at the 16 MiB limit.
    esi::test::TempDir dir;
    std::filesystem::create_symlink("/dev/zero", dir / "device.yaml");
    const auto gen = run_child({esi::test::tool("esi-gen").string(), (dir / "device.yaml").string(), "-o", (dir / "out").string()});
    EXPECT_EQ(gen.exit_code, 2) << gen.err;
    EXPECT_NE(gen.err.find("[io-error]"), std::string::npos) << gen.err;
    EXPECT_NE(gen.err.find("larger than 16 MiB"), std::string::npos) << gen.err;
    EXPECT_LT(gen.max_rss_kb, 128 * 1024 * memory_scale());
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}
