// Determinism (issue 6 §3): the tools give byte-identical output on every run, whatever the
// number of worker threads. Reports feed CI diffs and generated files feed firmware builds, so a
// reordering between runs is a spurious change.

#include <gtest/gtest.h>

#include <thread>

#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

// What to lint: the corpus when present, else the sample and the rule fixtures.
std::vector<std::string> lint_inputs() {
    if (esi::test::have_shared_corpus()) return {esi::test::corpus_esi_dir().string()};
    return {(esi::test::source_dir() / "samples").string(), (esi::test::source_dir() / "tests/rules/fixtures").string()};
}

}  // namespace

TEST(Determinism, EsiLintReportsAreTheSameWithOneAndAllCores) {
    const unsigned cores = std::max(2u, std::thread::hardware_concurrency());
    for (const std::string format : {"json", "sarif", "text"}) {
        std::vector<std::string> outputs;
        for (const std::string& jobs : {std::string("1"), std::to_string(cores), std::string("16"), std::string("1")}) {
            std::vector<std::string> argv = {esi::test::tool("esi-lint").string(), "--format", format, "-j", jobs};
            for (const auto& input : lint_inputs()) argv.push_back(input);
            const auto lint = esi::test::run_child(argv);
            ASSERT_TRUE(lint.exit_code == 0 || lint.exit_code == 1) << lint.err;
            ASSERT_FALSE(lint.out.empty());
            outputs.push_back(lint.out);
        }
        for (std::size_t i = 1; i < outputs.size(); ++i)
            EXPECT_TRUE(outputs[i] == outputs[0]) << format << ": run " << i << " differs from the -j 1 run";
    }
}

TEST(Determinism, EsiSiiBuildsTheSameBytesTwice) {
    esi::test::TempDir dir;
    const auto sample = (esi::test::source_dir() / "samples/esi/example-digital-io.xml").string();
    for (const std::string format : {"bin", "hex", "c"}) {
        const auto a = dir / ("a." + format), b = dir / ("b." + format);
        ASSERT_EQ(esi::test::run_child({esi::test::tool("esi-sii").string(), "build", sample, "--format", format, "-o", a.string()})
                      .exit_code,
                  0);
        ASSERT_EQ(esi::test::run_child({esi::test::tool("esi-sii").string(), "build", sample, "--format", format, "-o", b.string()})
                      .exit_code,
                  0);
        EXPECT_EQ(esi::test::read_text(a), esi::test::read_text(b)) << format;
    }
}

TEST(Determinism, EsiGenWritesTheSameFilesTwice) {
    // An ESI source and a YAML source (derivation runs too).
    for (const std::string relative : {"samples/esi/example-digital-io.xml", "samples/servo-item-c-series.yaml"}) {
        esi::test::TempDir dir;
        const auto sample = (esi::test::source_dir() / relative).string();
        for (const std::string out : {"first", "second"}) {
            const auto gen = esi::test::run_child({esi::test::tool("esi-gen").string(), sample, "-o", (dir / out).string()});
            ASSERT_EQ(gen.exit_code, 0) << relative << ": " << gen.err;
        }
        const auto first = esi::test::snapshot(dir / "first");
        const auto second = esi::test::snapshot(dir / "second");
        EXPECT_GE(first.size(), 5u) << relative;
        EXPECT_TRUE(first == second) << relative << ": esi-gen wrote different files on the second run";
    }
}

TEST(Determinism, EsiDiffReportsAreTheSameTwice) {
    std::vector<std::pair<std::string, std::string>> pairs = {
        {(esi::test::source_dir() / "tests/diff/data/old.xml").string(), (esi::test::source_dir() / "tests/diff/data/new.xml").string()}};
    if (esi::test::have_shared_corpus())
        pairs.emplace_back((esi::test::corpus_esi_dir() / "Beckhoff__EK13xx__dls-ethercat__2018-01.xml").string(),
                           (esi::test::corpus_esi_dir() / "Beckhoff__EK13xx__dls-ethercat__2018-06.xml").string());
    for (const auto& [old_file, new_file] : pairs) {
        for (const std::string format : {"json", "text", "markdown"}) {
            const auto a = esi::test::run_child({esi::test::tool("esi-diff").string(), old_file, new_file, "--format", format});
            const auto b = esi::test::run_child({esi::test::tool("esi-diff").string(), old_file, new_file, "--format", format});
            ASSERT_TRUE(a.exit_code == 0 || a.exit_code == 1) << a.err;
            EXPECT_FALSE(a.out.empty());
            EXPECT_EQ(a.exit_code, b.exit_code);
            EXPECT_TRUE(a.out == b.out) << format << ": " << new_file;
        }
    }
}
