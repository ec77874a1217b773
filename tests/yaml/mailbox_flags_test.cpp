// The mailbox protocol flag tables (esi/model/mailbox_flags.hpp) against every layer that reads
// or writes the flags: each flag set in an ESI file reaches its model field, the ESI writer
// writes it back, the import writes it under the table's key, the YAML format accepts that key,
// and the YAML front end reads it into the same field.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "esi/import/import.hpp"
#include "esi/model/mailbox_flags.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "esi/yaml/format_keys.hpp"
#include "yaml/yaml_test_support.hpp"

namespace {

template <class Protocol, std::size_t N>
std::string attributes(const esi::MailboxFlag<Protocol> (&flags)[N]) {
    std::string out;
    for (const auto& flag : flags) out += " " + std::string(flag.attribute) + "=\"true\"";
    return out;
}

template <class Protocol, std::size_t N>
void expect_all_set(const std::optional<Protocol>& protocol, const esi::MailboxFlag<Protocol> (&flags)[N], const char* where) {
    ASSERT_TRUE(protocol) << where;
    for (const auto& flag : flags) EXPECT_EQ((*protocol).*flag.field, true) << where << ": " << flag.attribute;
    EXPECT_TRUE(protocol->extras.empty()) << where;
}

template <class Protocol, std::size_t N>
void expect_keys_accepted(esi::yaml::Context context, const esi::MailboxFlag<Protocol> (&flags)[N]) {
    const auto keys = esi::yaml::keys_of(context).keys;
    for (const auto& flag : flags) EXPECT_NE(std::find(keys.begin(), keys.end(), flag.key), keys.end()) << flag.key;
}

void expect_every_flag_set(const esi::Mailbox& m, const char* where) {
    expect_all_set(m.coe, esi::coe_flags, where);
    expect_all_set(m.eoe, esi::eoe_flags, where);
    expect_all_set(m.soe, esi::soe_flags, where);
    expect_all_set(m.aoe, esi::aoe_flags, where);
}

}  // namespace

TEST(MailboxFlags, YamlFormatAcceptsEveryKey) {
    expect_keys_accepted(esi::yaml::Context::coe, esi::coe_flags);
    expect_keys_accepted(esi::yaml::Context::eoe, esi::eoe_flags);
    expect_keys_accepted(esi::yaml::Context::soe, esi::soe_flags);
    expect_keys_accepted(esi::yaml::Context::aoe, esi::aoe_flags);
}

TEST(MailboxFlags, EveryFlagSurvivesReaderWriterImportAndYaml) {
    const std::string xml = R"(<?xml version="1.0"?>
<EtherCATInfo Version="1.17">
  <Vendor><Id>#x0E4A</Id><Name>V</Name></Vendor>
  <Descriptions>
    <Groups><Group><Type>IO</Type><Name>IO</Name></Group></Groups>
    <Devices>
      <Device Physics="YY">
        <Type ProductCode="#x10" RevisionNo="#x1">X1</Type>
        <Name>X1</Name>
        <GroupType>IO</GroupType>
        <Sm StartAddress="#x1000" ControlByte="#x26" DefaultSize="128" Enable="1">MBoxOut</Sm>
        <Sm StartAddress="#x1080" ControlByte="#x22" DefaultSize="128" Enable="1">MBoxIn</Sm>
        <Mailbox>
          <AoE)" + attributes(esi::aoe_flags) + R"(/>
          <EoE)" + attributes(esi::eoe_flags) + R"(/>
          <CoE)" + attributes(esi::coe_flags) + R"(/>
          <SoE ChannelCount="2")" + attributes(esi::soe_flags) + R"(/>
        </Mailbox>
      </Device>
    </Devices>
  </Descriptions>
</EtherCATInfo>
)";
    const esi::ReadResult read = esi::read_esi(xml, "flags.xml");
    ASSERT_TRUE(read.document);
    EXPECT_TRUE(read.diagnostics.empty()) << esi::test::describe(read.diagnostics);
    const esi::Device& device = read.document->infos.at(0).devices.at(0);
    expect_every_flag_set(*device.mailbox, "read");
    EXPECT_EQ(device.mailbox->soe->channel_count, 2);

    const std::string written = esi::write_esi(*read.document);
    for (const std::string_view expected : {attributes(esi::aoe_flags), attributes(esi::eoe_flags), attributes(esi::coe_flags),
                                            attributes(esi::soe_flags)}) {
        // CoE's flags are split around EdsFile and DS402Channels, which this device lacks.
        EXPECT_NE(written.find(expected), std::string::npos) << expected << "\n" << written;
    }

    const esi::ImportResult imported = esi::import_device_source(*read.document);
    ASSERT_TRUE(imported.yaml) << esi::test::describe(imported.diagnostics);
    for (const auto& flag : esi::coe_flags)
        EXPECT_NE(imported.yaml->find(std::string(flag.key) + ": true"), std::string::npos) << flag.key << "\n" << *imported.yaml;
    const esi::DeviceSource loaded = esi::test::load_yaml(*imported.yaml, "flags.yaml");
    ASSERT_TRUE(loaded.document) << esi::test::describe(loaded.diagnostics) << *imported.yaml;
    expect_every_flag_set(*esi::test::only_device(loaded).mailbox, "yaml");
}
