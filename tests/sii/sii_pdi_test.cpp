// An image must let the microcontroller reach the ESC (issue 23): without ConfigData the builder
// warns that PDI control is 0 (an error when asked to refuse), the decoder reports PDI control 0
// on an image with a mailbox or PDOs unless the ESC emulates the device, and the dump names the
// PDI type of word 0.

#include <gtest/gtest.h>

#include "esi/sii/decode.hpp"
#include "esi/sii/render.hpp"
#include "fixture.hpp"

namespace {

using namespace esi::sii;
using esi::Severity;
using esi::test::build_fixture;
using esi::test::fixture_xml;
using esi::test::has_rule;

std::string with_config_data(const std::string& config) {
    std::string xml = fixture_xml();
    const std::string old = "<ConfigData>0E05030610270000</ConfigData>";
    xml.replace(xml.find(old), old.size(), config.empty() ? std::string() : "<ConfigData>" + config + "</ConfigData>");
    return xml;
}

bool has_fault(const DecodedImage& d, const std::string& rule) {
    for (const auto& f : d.faults)
        if (f.rule == rule) return true;
    return false;
}

TEST(SiiPdi, NoConfigDataIsAWarningNamingThePresetsOrAnErrorWhenRefused) {
    const BuildResult r = build_fixture(with_config_data(""));
    EXPECT_TRUE(r.ok());
    ASSERT_TRUE(has_rule(r.diagnostics, "sii-pdi-off", Severity::warning));
    bool names_presets = false;
    for (const auto& d : r.diagnostics)
        if (d.rule == "sii-pdi-off") names_presets = d.message.find("esc: lan9252-spi") != std::string::npos;
    EXPECT_TRUE(names_presets);

    BuildOptions refuse;
    refuse.refuse_pdi_off = true;
    const BuildResult refused = build_fixture(with_config_data(""), refuse);
    EXPECT_FALSE(refused.ok());
    EXPECT_TRUE(has_rule(refused.diagnostics, "sii-pdi-off", Severity::error));

    // With ConfigData there is nothing to say.
    const BuildResult spi = build_fixture(with_config_data("050E034464000000"));
    EXPECT_FALSE(has_rule(spi.diagnostics, "sii-pdi-off", Severity::warning));
}

TEST(SiiPdi, DecoderReportsPdiOffOnADeviceWithAMailboxUnlessTheEscEmulatesIt) {
    const DecodedImage off = decode_image(build_fixture(with_config_data("")).bytes);
    EXPECT_TRUE(has_fault(off, "sii-pdi-off"));
    EXPECT_TRUE(off.has_errors());

    const DecodedImage zero = decode_image(build_fixture(with_config_data("0000")).bytes);
    EXPECT_TRUE(has_fault(zero, "sii-pdi-off"));

    const DecodedImage emulated = decode_image(build_fixture(with_config_data("0001")).bytes);
    EXPECT_FALSE(has_fault(emulated, "sii-pdi-off"));

    const DecodedImage spi = decode_image(build_fixture(with_config_data("050E034464000000")).bytes);
    EXPECT_FALSE(has_fault(spi, "sii-pdi-off"));
}

TEST(SiiPdi, DumpNamesThePdiType) {
    const DecodedImage spi = decode_image(build_fixture(with_config_data("050E034464000000")).bytes);
    const std::string text = render_dump_text(spi, "spi.bin");
    EXPECT_NE(text.find("0x00 PDI control               0x0E05 (PDI SPI)"), std::string::npos) << text;
    EXPECT_NE(render_dump_json(spi, "spi.bin").find("\"pdi_type\": \"PDI SPI\""), std::string::npos);

    const DecodedImage bus = decode_image(build_fixture(with_config_data("8006E08800000000")).bytes);
    EXPECT_NE(render_dump_text(bus, "bus.bin").find("(PDI on-chip bus)"), std::string::npos);

    const DecodedImage off = decode_image(build_fixture(with_config_data("")).bytes);
    const std::string off_text = render_dump_text(off, "off.bin");
    EXPECT_NE(off_text.find("0x0000 (PDI off (no interface))"), std::string::npos) << off_text;
    EXPECT_NE(off_text.find("[sii-pdi-off]"), std::string::npos) << off_text;

    const DecodedImage odd = decode_image(build_fixture(with_config_data("42")).bytes);
    EXPECT_NE(render_dump_text(odd, "odd.bin").find("PDI type 0x42, not one the ESC datasheets define"), std::string::npos);
}

}  // namespace
