// The CI recipes users copy (docs/ci-integration.md) and the pre-commit hook definition
// (.pre-commit-hooks.yaml): every YAML block parses, the hook selects ESI files and runs a tool
// that exists, and the workflows call the tools with flags the tools accept.

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "esi/yaml/tree.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::read_text;
using esi::test::run;
using esi::test::tool;

std::vector<std::string> yaml_blocks(const std::string& markdown) {
    std::vector<std::string> blocks;
    const std::string open = "```yaml\n";
    for (auto at = markdown.find(open); at != std::string::npos; at = markdown.find(open, at)) {
        at += open.size();
        const auto end = markdown.find("```", at);
        if (end == std::string::npos) break;
        blocks.push_back(markdown.substr(at, end - at));
        at = end + 3;
    }
    return blocks;
}

std::unique_ptr<esi::yaml::Tree> parse(const std::string& text, const std::string& what) {
    esi::Diagnostics diagnostics;
    bool empty = false;
    auto tree = esi::yaml::Tree::parse(text, what, {}, diagnostics, empty);
    EXPECT_TRUE(tree && !diagnostics.has_errors()) << what << " is not YAML:\n" << text;
    return tree;
}

// The scalar under `key` of a map node; empty when absent.
std::string value_of(esi::yaml::Node map, std::string_view key) {
    for (auto it = map.begin(); it != map.end(); ++it) {
        if (it->first.IsScalar() && it->first.Scalar() == key && it->second.IsScalar()) return it->second.Scalar();
    }
    return {};
}

TEST(CiIntegration, EveryYamlBlockOfTheGuideParses) {
    const std::string guide = read_text(esi::test::source_dir() / "docs" / "ci-integration.md");
    const auto blocks = yaml_blocks(guide);
    ASSERT_EQ(blocks.size(), 4u) << "pre-commit (2), GitHub Actions, GitLab CI";
    for (std::size_t i = 0; i < blocks.size(); ++i) parse(blocks[i], "docs/ci-integration.md block " + std::to_string(i + 1));
}

TEST(CiIntegration, WorkflowsUploadSarifCommentDiffsAndReportCodeQuality) {
    const std::string guide = read_text(esi::test::source_dir() / "docs" / "ci-integration.md");
    const auto blocks = yaml_blocks(guide);
    ASSERT_EQ(blocks.size(), 4u);
    const std::string& github = blocks[2];
    EXPECT_NE(github.find("esi-lint --format sarif"), std::string::npos);
    EXPECT_NE(github.find("uses: github/codeql-action/upload-sarif@"), std::string::npos);
    EXPECT_NE(github.find("esi-diff --format markdown"), std::string::npos);
    EXPECT_NE(github.find("createComment"), std::string::npos);
    const std::string& gitlab = blocks[3];
    EXPECT_NE(gitlab.find("esi-lint --format gitlab"), std::string::npos);
    EXPECT_NE(gitlab.find("codequality: gl-code-quality-report.json"), std::string::npos);
    // The GitHub recipe's two commands work as written.
    const auto sample = (esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml").string();
    const auto sarif = run({tool("esi-lint"), "--format", "sarif", sample});
    EXPECT_EQ(sarif.exit_code, 0) << sarif.err;
    EXPECT_NE(sarif.out.find("\"version\": \"2.1.0\""), std::string::npos) << sarif.out;
    const auto diff = run({tool("esi-diff"), "--format", "markdown", sample, sample});
    EXPECT_EQ(diff.exit_code, 0) << diff.err;
    EXPECT_NE(diff.out.find("### esi-diff"), std::string::npos) << diff.out;
}

TEST(CiIntegration, PreCommitHookLintsXmlFilesWithEsiLint) {
    const auto tree = parse(read_text(esi::test::source_dir() / ".pre-commit-hooks.yaml"), ".pre-commit-hooks.yaml");
    ASSERT_TRUE(tree);
    const esi::yaml::Node hooks(tree->root());
    ASSERT_TRUE(hooks.IsSequence());
    ASSERT_EQ(hooks.size(), 1u);
    const esi::yaml::Node hook = *hooks.begin();
    EXPECT_EQ(value_of(hook, "id"), "esi-lint");
    EXPECT_EQ(value_of(hook, "entry"), "esi-lint");
    EXPECT_EQ(value_of(hook, "language"), "system");
    // pre-commit matches `files` with Python's re.search; this pattern means the same in ECMAScript.
    const std::regex files(value_of(hook, "files"));
    EXPECT_TRUE(std::regex_search("esi/Example Device.xml", files));
    EXPECT_FALSE(std::regex_search("device.yaml", files));
    EXPECT_FALSE(std::regex_search("notes.xml.txt", files));
    // pre-commit runs `entry FILE...`: esi-lint on the staged files.
    const auto sample = esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml";
    const auto r = run({tool(value_of(hook, "entry")), sample.string(), sample.string()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
