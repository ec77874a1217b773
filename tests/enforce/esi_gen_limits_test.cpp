// esi-gen and limits, as a firmware build calls it: a source that breaks its limits (its own, or
// those of --config) stops the run with a located error and exit 2, and nothing is written; the
// samples generate under their own limits and under their shipped profiles.

#include <gtest/gtest.h>

#include "codegen/codegen_test_support.hpp"
#include "enforce/enforce_test_support.hpp"

namespace {

namespace tc = esi::test::codegen;
using esi::test::source_dir;
using esi::test::TempDir;
using esi::test::write_text;
using esi::test::enforce::line_of;

std::filesystem::path sample(const std::string& name) { return source_dir() / "samples" / name; }
std::filesystem::path profile(const std::string& name) { return source_dir() / "samples" / "profiles" / name; }

// Runs esi-gen on `text` (written as inverter.yaml) into an output directory that already holds
// a file, and checks that the run fails with exit 2 and leaves that directory as it was.
esi::test::RunResult expect_refused(const std::string& text, const std::vector<std::string>& extra = {}) {
    TempDir dir;
    write_text(dir / "inverter.yaml", text);
    const auto out = dir.path() / "out";
    write_text(out / "process_image.h", "previous");
    const auto r = tc::esi_gen(dir / "inverter.yaml", out, extra);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    const auto files = tc::tree(out);
    EXPECT_EQ(files.size(), 1u);
    EXPECT_EQ(files.count("process_image.h") ? files.at("process_image.h") : "", "previous");
    return r;
}

std::string located(const std::string& text, const std::string& needle, std::uint32_t column) {
    return "inverter.yaml:" + std::to_string(line_of(text, needle)) + ":" + std::to_string(column) + ": error: ";
}

TEST(EsiGenLimits, AFifthRxPdoStopsTheRun) {
    const std::string text = esi::test::enforce::stoeber_with_a_fifth_rx_pdo();
    const auto r = expect_refused(text);
    EXPECT_NE(r.err.find(located(text, "index: 0x1604", 9) + "the device declares 5 RxPdos; its profile allows at most 4"),
              std::string::npos)
        << r.err;
}

TEST(EsiGenLimits, SevenEntriesStopTheRun) {
    const std::string text = esi::test::enforce::stoeber_with_seven_entries();
    const auto r = expect_refused(text);
    EXPECT_NE(r.err.find(located(text, "index: 0x1600", 9) + "RxPdo #x1600 has 7 entries; the profile allows at most 6 per PDO "
                                                             "[profile-max-entries]"),
              std::string::npos)
        << r.err;
}

TEST(EsiGenLimits, AnInitCmdAtAnUnsupportedTransitionStopsTheRun) {
    const std::string text = esi::test::enforce::stoeber_with_an_init_cmd_at_ib();
    const auto r = expect_refused(text);
    EXPECT_NE(r.err.find(located(text, "transition: IB", 23) + "CoE InitCmd transition 'IB' is not one the profile allows"),
              std::string::npos)
        << r.err;
}

TEST(EsiGenLimits, AWrongStoeberParameterIndexStopsTheRun) {
    const std::string text = esi::test::enforce::stoeber_with_a180_at_20b5();
    const auto r = expect_refused(text);
    EXPECT_NE(r.err.find(located(text, "0x20B5:", 7) + "object #x20B5 is named 'A180 Device Control Byte', but parameter A180 "
                                                       "is at #x20B4"),
              std::string::npos)
        << r.err;
}

TEST(EsiGenLimits, AProfileGivenWithConfigHoldsAnEsiFileToo) {
    // The example ESI maps bytes; a profile that allows only 16- and 32-bit entries refuses it.
    TempDir dir;
    write_text(dir / "words.yaml", "limits: { bitlen: [16, 32] }\n");
    const auto out = dir.path() / "out";
    const auto esi = sample("esi/example-digital-io.xml");
    const auto r = tc::esi_gen(esi, out, {"--only", "structs", "--config", (dir / "words.yaml").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("example-digital-io.xml:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("[profile-bitlen]"), std::string::npos) << r.err;
    EXPECT_TRUE(tc::tree(out).empty());
    // Without it, the same file generates.
    EXPECT_EQ(tc::esi_gen(esi, out, {"--only", "structs"}).exit_code, 0);
}

TEST(EsiGenLimits, ARuleTheProfileGradesAsWarningIsPrintedAndTheRunGoesOn) {
    TempDir dir;
    write_text(dir / "lenient.yaml", "rules: { profile-bitlen: warning }\nlimits: { bitlen: [16, 32] }\n");
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(sample("esi/example-digital-io.xml"), out, {"--only", "structs", "--config", (dir / "lenient.yaml").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: "), std::string::npos);
    EXPECT_NE(r.err.find("[profile-bitlen]"), std::string::npos);
    EXPECT_EQ(tc::tree(out).size(), 1u);
}

TEST(EsiGenLimits, AnUnusableConfigIsExitTwo) {
    TempDir dir;
    write_text(dir / "typo.yaml", "limits:\n  max_pdo: 4\n");
    const auto out = dir.path() / "out";
    const auto typo = tc::esi_gen(sample("digital-io-8.yaml"), out, {"--config", (dir / "typo.yaml").string()});
    EXPECT_EQ(typo.exit_code, 2);
    EXPECT_NE(typo.err.find("typo.yaml:2:3: error: "), std::string::npos) << typo.err;
    const auto missing = tc::esi_gen(sample("digital-io-8.yaml"), out, {"--config", (dir / "none.yaml").string()});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("none.yaml"), std::string::npos) << missing.err;
    EXPECT_TRUE(tc::tree(out).empty());
}

TEST(EsiGenLimits, TheSamplesGenerateUnderTheirOwnLimitsAndTheirProfiles) {
    const std::pair<const char*, const char*> samples[] = {
        {"servo-item-c-series.yaml", "servo-item-afag.yaml"}, {"inverter-stoeber-mds5000.yaml", "inverter-stoeber.yaml"},
        {"encoder-tr-linear.yaml", "encoder-tr.yaml"},        {"digital-io-8.yaml", nullptr},
        {"modular-coupler.yaml", nullptr},
    };
    for (const auto& [name, profile_name] : samples) {
        SCOPED_TRACE(name);
        TempDir dir;
        const auto own = tc::esi_gen(sample(name), dir.path() / "own");
        EXPECT_EQ(own.exit_code, 0) << own.err;
        EXPECT_FALSE(tc::tree(dir.path() / "own").empty());
        if (!profile_name) continue;
        const auto with_profile = tc::esi_gen(sample(name), dir.path() / "profiled", {"--config", profile(profile_name).string()});
        EXPECT_EQ(with_profile.exit_code, 0) << with_profile.err;
        EXPECT_EQ(with_profile.err, own.err);  // no finding beyond what generation itself notes
        EXPECT_EQ(tc::tree(dir.path() / "profiled"), tc::tree(dir.path() / "own"));
    }
}

}  // namespace
