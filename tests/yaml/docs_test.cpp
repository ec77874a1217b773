// docs/yaml-format.md against the parser: the key reference lists every key of every mapping,
// and the short example loads and derives what the text says it does.

#include <gtest/gtest.h>

#include "esi/yaml/format_keys.hpp"
#include "yaml/yaml_test_support.hpp"

using namespace esi;

namespace {

std::string doc() { return esi::test::read_text(esi::test::source_dir() / "docs" / "yaml-format.md"); }

// The text between "### `name`" and the next heading.
std::string section(const std::string& text, const std::string& name) {
    const std::string heading = "### `" + name + "`\n";
    const auto start = text.find(heading);
    if (start == std::string::npos) return {};
    const auto end = text.find("\n#", start + heading.size());
    return text.substr(start + heading.size(), end == std::string::npos ? std::string::npos : end - start - heading.size());
}

}  // namespace

TEST(YamlDocs, KeyReferenceListsEveryKey) {
    const std::string text = doc();
    for (const auto& c : esi::yaml::format_contexts()) {
        SCOPED_TRACE(std::string(c.name));
        const std::string body = section(text, std::string(c.name));
        ASSERT_FALSE(body.empty()) << "no section for " << c.name;
        for (std::string_view key : c.keys)
            EXPECT_NE(body.find("`" + std::string(key) + "`"), std::string::npos) << key << " is not documented";
    }
}

TEST(YamlDocs, TheShortExampleLoadsAndDerivesWhatTheTextSays) {
    const std::string text = doc();
    const auto start = text.find("```yaml\nvendor:");
    ASSERT_NE(start, std::string::npos);
    const auto body = start + 8;
    const std::string example = text.substr(body, text.find("```", body) - body);
    const DeviceSource s = esi::test::load_yaml(example);
    ASSERT_TRUE(s.diagnostics.empty()) << esi::test::describe(s.diagnostics);
    const Device& d = esi::test::only_device(s);
    ASSERT_EQ(d.sms.size(), 4u);
    EXPECT_EQ(d.sms[2].start_address, 0x1100u);
    EXPECT_EQ(d.sms[2].default_size, 8u);
    EXPECT_EQ(d.sms[3].start_address, 0x1180u);
    EXPECT_EQ(d.sms[3].default_size, 6u);
    EXPECT_EQ(d.fmmus.size(), 3u);
    for (std::uint32_t index : {0x1000u, 0x1018u, 0x1600u, 0x1A00u, 0x1C00u, 0x1C12u, 0x1C13u})
        EXPECT_NE(d.dictionary()->find_object(index), nullptr) << std::hex << index;
    EXPECT_EQ(d.mailbox->coe->init_cmds.at(0).data.text, "08");
}
