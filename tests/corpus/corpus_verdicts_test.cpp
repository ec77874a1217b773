// The ecosystem check, after Ruff's ecosystem CI and mypy_primer: esi-lint, as shipped (every rule
// at its default severity), over every real file of ../shared/corpus/esi, compared with the
// reviewed snapshot tests/corpus/expected/verdicts.tsv (file, rule, severity, count). Any change
// of verdict on real files fails here until the snapshot is regenerated and the change reviewed:
// scripts/corpus-verdicts.sh prints the change per rule and the files whose pass/fail flips, and
// --update writes the new snapshot. Skipped when ../shared is absent.
//
// With ESI_CORPUS_VERDICTS_OUT=FILE in the environment the current table is also written to FILE
// (that is how the script regenerates the snapshot).

#include <gtest/gtest.h>

#include <cstdlib>

#include "corpus/verdict_table.hpp"
#include "support/test_support.hpp"

namespace {

const std::filesystem::path expected_dir = esi::test::source_dir() / "tests" / "corpus" / "expected";

esi::test::Origins corpus_origins() { return esi::test::parse_origins(esi::test::read_text(expected_dir / "origins.tsv")); }

TEST(CorpusVerdicts, EveryCorpusFileHasAnOrigin) {
    ESI_REQUIRE_CORPUS();
    const auto origins = corpus_origins();
    for (const auto& entry : std::filesystem::directory_iterator(esi::test::corpus_esi_dir())) {
        if (entry.path().extension() != ".xml") continue;
        const std::string file = entry.path().filename().string();
        EXPECT_TRUE(origins.count(file)) << file << " has no line in tests/corpus/expected/origins.tsv";
    }
    for (const auto& [file, origin] : origins) {
        EXPECT_TRUE(std::filesystem::exists(esi::test::corpus_esi_dir() / file)) << file << " is not in the corpus";
        EXPECT_TRUE(origin == "official" || origin == "edited" || origin == "assembled" || origin == "generated" ||
                    origin == "example" || origin == "hobby" || origin == "test")
            << file << ": unknown origin '" << origin << "'";
    }
}

TEST(CorpusVerdicts, MatchTheReviewedSnapshot) {
    ESI_REQUIRE_CORPUS();
    const std::string corpus = esi::test::corpus_esi_dir().string();
    // An explicit config that changes nothing, so that no .esi-lint.yaml above the corpus can
    // change the verdicts.
    const auto run = esi::test::run({esi::test::tool("esi-lint").string(), "--format", "json", "--fail-on", "never",
                                     "--config", (expected_dir / "shipped-defaults.esi-lint.yaml").string(), corpus});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto now = esi::test::verdicts_from_lint_json(run.out, corpus);
    ASSERT_FALSE(now.empty());
    if (const char* out = std::getenv("ESI_CORPUS_VERDICTS_OUT"); out && *out)
        esi::test::write_text(out, esi::test::format_verdicts(now));

    const auto snapshot = esi::test::parse_verdicts(esi::test::read_text(expected_dir / "verdicts.tsv"));
    const std::string change = esi::test::describe_change(snapshot, now, corpus_origins());
    // The account goes to stdout whether or not it matches (scripts/corpus-verdicts.sh shows it).
    std::printf("%s", change.c_str());
    EXPECT_TRUE(snapshot == now) << "esi-lint's verdicts on the corpus differ from tests/corpus/expected/verdicts.tsv "
                                    "(account above). Review the change, then run scripts/corpus-verdicts.sh --update "
                                    "and commit the snapshot with it.";
}

}  // namespace
