// The seed samples and the shipped profiles of their device families (samples/profiles/): each
// sample declares every limit its profile sets (so esi-gen holds it to them without --config),
// and the ESI written from it is clean under the profile as esi-lint applies it.

#include <gtest/gtest.h>

#include "esi/check/run.hpp"
#include "esi/lint/config.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "yaml/yaml_test_support.hpp"

using namespace esi;
using esi::test::describe;
using esi::test::sample_path;

namespace {

const std::pair<const char*, const char*> seed_samples[] = {
    {"servo-item-c-series.yaml", "servo-item-afag.yaml"},
    {"inverter-stoeber-mds5000.yaml", "inverter-stoeber.yaml"},
    {"encoder-tr-linear.yaml", "encoder-tr.yaml"},
};

EffectiveConfig profile_for(const std::string& profile, const std::filesystem::path& file) {
    const auto path = sample_path("profiles/" + profile);
    const ConfigResult loaded = load_lint_config(path);
    EXPECT_TRUE(loaded.config) << describe(loaded.diagnostics);
    return loaded.config ? effective_config(*loaded.config, file) : EffectiveConfig{};
}

}  // namespace

TEST(YamlSamplesAndProfiles, EverySampleDeclaresWhatItsProfileSets) {
    for (const auto& [sample, profile] : seed_samples) {
        SCOPED_TRACE(sample);
        const DeviceSource s = load_device_source_file(sample_path(sample));
        ASSERT_EQ(s.device_limits.size(), 1u);
        const Limits& declared = s.device_limits[0].second;
        // The sample's limits on top of the profile's change nothing: it sets every field the
        // profile sets (possibly stricter, e.g. the servo's longer absent_objects).
        Limits merged = profile_for(profile, sample_path(sample)).limits;
        EXPECT_FALSE(merged.empty());
        merged.merge(declared);
        EXPECT_TRUE(merged == declared);
    }
}

TEST(YamlSamplesAndProfiles, TheWrittenEsiIsCleanUnderTheProfile) {
    for (const auto& [sample, profile] : seed_samples) {
        SCOPED_TRACE(sample);
        const DeviceSource s = load_device_source_file(sample_path(sample));
        ASSERT_TRUE(s.document) << describe(s.diagnostics);
        const std::string xml = write_esi(*s.document);
        const ReadResult back = read_esi(xml, std::string(sample) + ".xml");
        ASSERT_TRUE(back.document) << describe(back.diagnostics);
        const EffectiveConfig config = profile_for(profile, sample_path(sample));
        ASSERT_FALSE(config.limits.empty());
        const Diagnostics found = run_rules(*back.document, config);
        std::size_t profile_findings = 0;
        for (const auto& d : found) profile_findings += d.rule.starts_with("profile-") ? 1 : 0;
        EXPECT_EQ(profile_findings, 0u) << describe(found);
    }
}
