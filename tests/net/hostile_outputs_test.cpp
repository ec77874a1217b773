// Whatever a name or comment holds, every output is what the docs promise (issue 27, item 3):
// network.xml and lcec.xml well-formed (and the ENI schema-valid), igh_config.c compiles with
// -Werror, process_image.md carries no raw HTML and no process_image.csv cell starts a formula.

#include <gtest/gtest.h>

#include "esi/net/network_spec.hpp"
#include "esi/net/outputs.hpp"
#include "net/hostile_esi.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

bool have(const std::string& program) { return esi::test::run({"sh", "-c", "command -v " + program}).exit_code == 0; }

// Control characters (as YAML escapes), markup, comment and CDATA ends, C comment and trigraph
// sequences, a bidi override and formula starts.
const std::string hostile_yaml_text = R"(\x01\0\e\uFFFE --> ]]> */ /* ??/ ??= <script>x</script> \u202E)";

struct HostileNetwork {
    esi::test::TempDir dir;
    std::optional<esi::net::Network> network;
    std::string diagnostics;
    std::string out(const std::string& file) const { return esi::test::read_text(dir / "out" / file); }

    explicit HostileNetwork(const std::string& sdo_extra = "") {
        esi::test::HostileDevice d;
        d.coe = true;
        d.name = "<script>alert(1)</script>";
        d.entry_name = "=HYPERLINK(\"http://x\")<img src=x onerror=alert(1)>";
        d.type = "Hostile";
        esi::test::write_text(dir / "lib.xml", d.xml());
        const std::string yaml = "master: { name: \"" + hostile_yaml_text + "\" }\nslaves:\n  - name: \"=1+2 " + hostile_yaml_text +
                                 "\"\n    device: Hostile\n    sdos: [{ index: 0x2000, type: UDINT, value: 1, comment: \"" + hostile_yaml_text +
                                 "\"" + sdo_extra + " }]\n  - { name: \"@SUM(1) -2 +3\", device: Hostile }\n";
        const esi::net::NetworkFileResult read = esi::net::read_network_text(yaml, (dir / "n.yaml").string());
        diagnostics = esi::test::diagnostics_text(read.diagnostics);
        if (!read.spec) return;
        esi::net::BuildOptions options;
        options.extra_esi = {dir / "lib.xml"};
        esi::net::BuildResult built = esi::net::build_network(*read.spec, options);
        diagnostics += esi::test::diagnostics_text(built.diagnostics);
        network = std::move(built.network);
        if (!network) return;
        const auto kinds = esi::net::all_output_kinds();
        const std::vector<esi::net::OutputKind> all(kinds.begin(), kinds.end());
        for (const esi::OutputFile& f : esi::net::network_outputs(*network, all, dir / "out")) esi::test::write_text(f.path, f.content);
    }
};

TEST(HostileOutputs, XmlOutputsAreWellFormedAndTheEniIsSchemaValid) {
    if (!have("xmllint")) GTEST_SKIP() << "xmllint not installed: well-formedness check skipped";
    HostileNetwork n;
    ASSERT_TRUE(n.network) << n.diagnostics;
    for (const std::string file : {"network.xml", "lcec.xml"}) {
        const auto r = esi::test::run({"xmllint", "--noout", (n.dir / "out" / file).string()});
        EXPECT_EQ(r.exit_code, 0) << file << "\n" << r.err;
    }
    const fs::path xsd = esi::test::corpus_dir() / "schema" / "eni-v1.6" / "EtherCATConfig.xsd";
    if (!fs::exists(xsd)) GTEST_SKIP() << "../shared/corpus not present: schema check skipped";
    const auto r = esi::test::run({"xmllint", "--noout", "--schema", xsd.string(), (n.dir / "out" / "network.xml").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(HostileOutputs, TheIghSourceCompilesWithWerror) {
    const fs::path igh = esi::test::igh_api_dir();
    if (!have("gcc")) GTEST_SKIP() << "no gcc: compile check skipped";
    HostileNetwork n;
    ASSERT_TRUE(n.network) << n.diagnostics;
    for (const std::string standard : {"-std=c99", "-std=gnu89"}) {
        const auto r = esi::test::run({"gcc", standard, "-trigraphs", "-Wall", "-Wextra", "-Werror", "-Wbidi-chars=any", "-I" + igh.string(),
                                       "-c", (n.dir / "out" / "igh_config.c").string(), "-o", (n.dir / "c.o").string()});
        EXPECT_EQ(r.exit_code, 0) << standard << "\n" << r.err;
    }
}

TEST(HostileOutputs, TheMarkdownMapHasNoRawHtml) {
    HostileNetwork n;
    ASSERT_TRUE(n.network) << n.diagnostics;
    const std::string md = n.out("process_image.md");
    EXPECT_EQ(md.find('<'), std::string::npos) << md;
}

TEST(HostileOutputs, NoCsvCellStartsAFormula) {
    HostileNetwork n;
    ASSERT_TRUE(n.network) << n.diagnostics;
    const std::string csv = n.out("process_image.csv");
    // Cells follow a line start or a comma, optionally inside quotes.
    for (const char start : std::string("=+-@\t\r")) {
        for (const std::string before : {"\n", ",", "\n\"", ",\""}) {
            EXPECT_EQ(csv.find(before + start), std::string::npos) << "a cell starts with '" << start << "':\n" << csv;
        }
    }
}

TEST(HostileOutputs, AnSdoWithoutTransitionsOrDataIsRefused) {
    EXPECT_FALSE(HostileNetwork(", transition: []").network);
    const esi::net::NetworkFileResult r =
        esi::net::read_network_text("slaves:\n  - { device: X, sdos: [{ index: 0x2000, data: \"\" }] }\n", "n.yaml");
    EXPECT_FALSE(r.spec);
    EXPECT_NE(esi::test::diagnostics_text(r.diagnostics).find("n.yaml:2:"), std::string::npos) << esi::test::diagnostics_text(r.diagnostics);
}

}  // namespace
