// Every front end that reads ESI XML refuses a file that is not well-formed XML 1.0 although
// pugixml accepts it (issue 16): the same located xml-syntax error, the tool's exit code for a
// bad input, and nothing written.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::run;
using esi::test::tool;

struct Case {
    const char* name;
    std::string (*edit)(const std::string& sample);
    std::string position;  // line:column
};

std::string repeated_attribute(const std::string& sample) {
    return esi::test::replace_once(sample, "<Device Physics=\"YY\">", "<Device Physics=\"YY\" Physics=\"YY\">");
}
std::string less_than_in_a_value(const std::string& sample) {
    return esi::test::replace_once(sample, "<Device Physics=\"YY\">", "<Device Physics=\"Y<Y\">");
}
std::string control_character(const std::string& sample) {
    return esi::test::replace_once(sample, "<Device Physics=\"YY\">", "<Device Physics=\"YY\">\x01");
}

TEST(WellFormednessCli, EveryXmlFrontEndRefusesWhatPugixmlTolerates) {
    const std::string sample = esi::test::sample_esi();
    const std::uint32_t line = esi::test::line_of(sample, "<Device Physics=\"YY\">");
    ASSERT_GT(line, 0u);
    const std::size_t device = sample.find("<Device Physics");
    const std::size_t device_column = device - sample.rfind('\n', device);  // of the '<'
    const auto at = [&](std::size_t offset) { return std::to_string(line) + ":" + std::to_string(device_column + offset); };
    const std::vector<Case> cases = {
        {"repeated attribute", repeated_attribute, at(21)},
        {"'<' in a value", less_than_in_a_value, at(18)},
        {"U+0001 in text", control_character, at(21)},
    };
    esi::test::TempDir dir;
    const auto good = dir / "good.xml";
    esi::test::write_text(good, sample);
    const auto image = dir / "good.bin";
    ASSERT_EQ(run({tool("esi-sii").string(), "build", good.string(), "-o", image.string()}).exit_code, 0);
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const auto bad = dir / "bad.xml";
        esi::test::write_text(bad, c.edit(sample));
        const std::string located = bad.string() + ":" + c.position + ": error: not well-formed";
        const auto outputs = dir / "out";
        const std::vector<std::pair<std::vector<std::string>, int>> runs = {
            {{tool("esi-lint").string(), bad.string()}, 1},
            {{tool("esi-diff").string(), good.string(), bad.string()}, 2},
            {{tool("esi-gen").string(), "--import", bad.string(), "-o", (outputs / "device.yaml").string()}, 2},
            {{tool("esi-gen").string(), bad.string(), "-o", outputs.string()}, 2},
            {{tool("esi-sii").string(), "build", bad.string(), "-o", (outputs / "image.bin").string()}, 2},
            {{tool("esi-sii").string(), "check", bad.string(), image.string()}, 2},
        };
        for (const auto& [argv, exit_code] : runs) {
            SCOPED_TRACE(argv[0] + " " + argv[1]);
            const auto r = run(argv);
            EXPECT_EQ(r.exit_code, exit_code) << r.out << r.err;
            EXPECT_NE((r.out + r.err).find(located), std::string::npos) << r.out << r.err;
            EXPECT_NE((r.out + r.err).find("[xml-syntax]"), std::string::npos) << r.out << r.err;
            EXPECT_FALSE(std::filesystem::exists(outputs)) << "something was written";
        }
    }
}

}  // namespace
