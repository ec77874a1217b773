// `esc:` in a device source: a preset fills Eeprom ConfigData, ByteSize and BootStrap so that the
// image switches its PDI on; what `eeprom:` states wins; an unknown name or a complete image next
// to it is refused. Every sample names its ESC, and the schema offers exactly the presets.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "esi/model/esc_preset.hpp"
#include "yaml/yaml_test_support.hpp"

using namespace esi;
using esi::test::describe;
using esi::test::load_yaml;
using esi::test::only_device;

namespace {

std::string source_with(const std::string& device_keys) {
    return "vendor: { id: 0x0E4A, name: V }\n"
           "groups: [{ type: G, name: G }]\n"
           "devices:\n"
           "  - type: D\n"
           "    name: D\n"
           "    product_code: 1\n"
           "    revision: 1\n"
           "    group: G\n" +
           device_keys;
}

}  // namespace

TEST(EscPreset, FillsConfigDataSizeAndBootStrap) {
    const DeviceSource s = load_yaml(source_with("    esc: tiesc\n"));
    ASSERT_TRUE(s.document) << describe(s.diagnostics);
    EXPECT_TRUE(s.diagnostics.empty()) << describe(s.diagnostics);
    const Device& d = only_device(s);
    ASSERT_TRUE(d.eeprom && d.eeprom->config_data && d.eeprom->boot_strap);
    EXPECT_EQ(d.eeprom->config_data->text, "8006E08800000000");
    EXPECT_EQ(d.eeprom->byte_size, 2048u);
    EXPECT_EQ(d.eeprom->boot_strap->text, "0010000200120002");
    // Positions point at the `esc` value, so later diagnostics about them are located.
    EXPECT_EQ(d.eeprom->config_data->pos.line, 9u);
}

TEST(EscPreset, ExplicitEepromValuesWin) {
    const DeviceSource s =
        load_yaml(source_with("    esc: lan9252-spi\n    eeprom: { size: 4096, config_data: 8003006EFF00FF000000 }\n"));
    ASSERT_TRUE(s.document) << describe(s.diagnostics);
    const Device& d = only_device(s);
    ASSERT_TRUE(d.eeprom && d.eeprom->config_data);
    EXPECT_EQ(d.eeprom->config_data->text, "8003006EFF00FF000000");
    EXPECT_EQ(d.eeprom->byte_size, 4096u);
    EXPECT_FALSE(d.eeprom->boot_strap);

    // Only the ConfigData given: the preset's size still applies.
    const DeviceSource t = load_yaml(source_with("    esc: xmc4\n    eeprom: { config_data: 80068106 }\n"));
    ASSERT_TRUE(t.document) << describe(t.diagnostics);
    EXPECT_EQ(only_device(t).eeprom->byte_size, 3968u);
    EXPECT_EQ(only_device(t).eeprom->config_data->text, "80068106");
}

TEST(EscPreset, UnknownNameIsRefusedWithTheListAndASuggestion) {
    const DeviceSource s = load_yaml(source_with("    esc: lan9252-sip\n"));
    EXPECT_FALSE(s.document);
    const std::string text = describe(s.diagnostics);
    EXPECT_NE(text.find("9:10 error yaml-value: 'lan9252-sip' is not an ESC preset; did you mean 'lan9252-spi'? The presets are "
                        "lan9252-spi, ax58100-spi"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("config_data"), std::string::npos) << text;
}

TEST(EscPreset, CompleteImageExcludesAPreset) {
    const DeviceSource s = load_yaml(source_with("    esc: et1100-spi\n    eeprom: { data: 0500 }\n"));
    EXPECT_FALSE(s.document);
    EXPECT_NE(describe(s.diagnostics).find("yaml-conflict"), std::string::npos) << describe(s.diagnostics);
}

TEST(EscPreset, EveryPresetSwitchesThePdiOnAndFitsTheSizeWord) {
    for (const EscPreset& p : esc_presets()) {
        const auto config = p.config_bytes();
        ASSERT_GE(config.size(), 2u) << p.name;
        EXPECT_LE(config.size(), 14u) << p.name << ": words 0-6 only (word 7 is the CRC)";
        EXPECT_NE(config[0], 0) << p.name;
        EXPECT_TRUE(pdi_type_name(config[0])) << p.name;
        EXPECT_EQ(p.eeprom_bytes % 128, 0u) << p.name;
        EXPECT_TRUE(p.boot_strap.empty() || p.boot_strap_bytes().size() == 8) << p.name;
        EXPECT_EQ(find_esc_preset(p.name), &p);
        // Presets with the same values (et1200-spi is et1100-spi) match as the first of them.
        const EscPreset* matched = match_esc_preset(config, p.eeprom_bytes, p.boot_strap_bytes());
        ASSERT_NE(matched, nullptr) << p.name;
        EXPECT_LE(matched, &p) << p.name;
        EXPECT_EQ(matched->config_data, p.config_data) << p.name;
    }
    EXPECT_EQ(find_esc_preset("LAN9252-SPI"), nullptr);
    EXPECT_EQ(pdi_type_name(0x05), "SPI");
    EXPECT_EQ(pdi_type_name(0x00), "off (no interface)");
    EXPECT_FALSE(pdi_type_name(0x42));
}

TEST(EscPreset, SchemaOffersExactlyThePresets) {
    const auto schema = nlohmann::json::parse(esi::test::read_text(esi::test::source_dir() / "schemas" / "esi-device.schema.json"));
    const auto& offered = schema.at("definitions").at("device").at("properties").at("esc").at("enum");
    std::vector<std::string> names;
    for (const auto& p : esc_presets()) names.emplace_back(p.name);
    EXPECT_EQ(offered.get<std::vector<std::string>>(), names);
}

TEST(EscPreset, EverySampleNamesItsEscAndEnablesItsPdi) {
    for (const char* name : {"servo-item-c-series.yaml", "inverter-stoeber-mds5000.yaml", "encoder-tr-linear.yaml",
                             "digital-io-8.yaml", "modular-coupler.yaml"}) {
        const std::string text = esi::test::read_text(esi::test::sample_path(name));
        EXPECT_NE(text.find("\n    esc: "), std::string::npos) << name;
        const DeviceSource s = load_device_source_file(esi::test::sample_path(name));
        ASSERT_TRUE(s.document) << name;
        for (const auto& d : s.document->infos.at(0).devices) {
            ASSERT_TRUE(d.eeprom && d.eeprom->config_data) << name;
            const auto bytes = d.eeprom->config_data->bytes();
            ASSERT_TRUE(bytes && !bytes->empty()) << name;
            EXPECT_NE((*bytes)[0], 0) << name << ": PDI control 0 (PDI off)";
        }
    }
}
