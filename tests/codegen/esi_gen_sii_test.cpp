// esi-gen writes the SII EEPROM image next to the ESI and the code (issue 5 §1), so that image,
// ESI and firmware tables come from one source. The image must be the one `esi-sii build` makes
// from the same source, and must check clean against the ESI written in the same run.

#include <gtest/gtest.h>

#include <cctype>

#include "codegen_test_support.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/image_file.hpp"

namespace {

namespace tc = esi::test::codegen;
using esi::test::read_text;
using esi::test::run;
using esi::test::source_dir;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::vector<std::uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

TEST(EsiGenSii, ImageEqualsEsiSiiBuildAndChecksCleanAgainstTheGeneratedEsi) {
    const auto source = source_dir() / "samples" / "servo-item-c-series.yaml";
    TempDir dir;
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(source, out, {"--only", "esi,sii"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto files = tc::tree(out);
    ASSERT_EQ(files.size(), 3u);
    const std::string& image = files.at("eeprom.bin");

    const auto built = dir.path() / "built.bin";
    const auto b = run({tool("esi-sii").string(), "build", source.string(), "-o", built.string()});
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_EQ(image, read_text(built));

    // The Intel HEX file holds the same bytes.
    const auto hex = esi::sii::parse_intel_hex(files.at("eeprom.hex"));
    ASSERT_TRUE(hex.bytes) << hex.error;
    EXPECT_EQ(*hex.bytes, bytes_of(image));

    // Consistent by construction: the image agrees with the ESI of the same run.
    const auto check = run({tool("esi-sii").string(), "check", (out / "servo-item-c-series.xml").string(), (out / "eeprom.bin").string()});
    EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
    const auto decoded = esi::sii::decode_image(bytes_of(image));
    EXPECT_TRUE(decoded.crc_ok);
    EXPECT_TRUE(decoded.faults.empty());
}

TEST(EsiGenSii, ImageThatDoesNotFitTheEepromWritesNothing) {
    // A 128-byte EEPROM holds the header only, not even the mandatory part of the image
    // (strings, General, FMMU, SyncM): the builder reports it, and esi-gen writes no file at all
    // (not even the code outputs).
    TempDir dir;
    std::string xml = read_text(tc::sample_esi());
    const auto at = xml.find("<ByteSize>");
    ASSERT_NE(at, std::string::npos) << "the sample is expected to declare Eeprom/ByteSize";
    const auto end = xml.find("</ByteSize>", at);
    xml.replace(at, end - at, "<ByteSize>128");
    write_text(dir / "small.xml", xml);
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(dir / "small.xml", out, {"--only", "cpp,sii"});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("[sii-"), std::string::npos) << r.err;
    EXPECT_TRUE(tc::tree(out).empty());
}

TEST(EsiGenSii, ImageLeavesOutOptionalContentToFitUnlessStrictSize) {
    // 384 bytes hold the sample device without its PDO categories (its CoE mailbox has SdoInfo).
    TempDir dir;
    std::string xml = read_text(tc::sample_esi());
    const auto at = xml.find("<ByteSize>");
    ASSERT_NE(at, std::string::npos);
    xml.replace(at, xml.find("</ByteSize>", at) - at, "<ByteSize>384");
    write_text(dir / "small.xml", xml);

    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(dir / "small.xml", out, {"--only", "sii"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("info: the TxPDO and RxPDO categories (2 PDOs) left out"), std::string::npos) << r.err;
    const auto files = tc::tree(out);
    ASSERT_EQ(files.at("eeprom.bin").size(), 384u);
    const auto decoded = esi::sii::decode_image(bytes_of(files.at("eeprom.bin")));
    EXPECT_TRUE(decoded.faults.empty());
    EXPECT_EQ(decoded.image.find(esi::sii::category::tx_pdo), nullptr);

    const auto strict_out = dir.path() / "strict";
    const auto strict = tc::esi_gen(dir / "small.xml", strict_out, {"--only", "cpp,sii", "--strict-size"});
    EXPECT_EQ(strict.exit_code, 1) << strict.err;
    EXPECT_NE(strict.err.find("[sii-image-too-large]"), std::string::npos) << strict.err;
    EXPECT_TRUE(tc::tree(strict_out).empty());
}

TEST(EsiGenSii, ListOutputsNamesTheImageFiles) {
    TempDir dir;
    const auto r = tc::esi_gen(tc::sample_esi(), dir.path(), {"--only", "sii", "--list-outputs"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("eeprom.bin\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("eeprom.hex\n"), std::string::npos) << r.out;
}

}  // namespace

namespace {

TEST(EsiGenSii, AnImageThatSwitchesThePdiOffIsAWarningAndWithStrictAnError) {
    // A minimal source without `esc:` and without Eeprom/ConfigData (issue 23).
    esi::test::TempDir dir;
    esi::test::write_text(dir / "min.yaml",
                          "vendor: { id: 0x0E4A, name: V }\n"
                          "devices:\n"
                          "  - type: EX-1\n"
                          "    name: Ex\n"
                          "    product_code: 1\n"
                          "    revision: 1\n"
                          "    mailbox: { size: 128, coe: {} }\n");
    const auto out = dir.path() / "out";
    const auto warned = tc::esi_gen(dir / "min.yaml", out, {"--only", "sii"});
    ASSERT_EQ(warned.exit_code, 0) << warned.err;
    EXPECT_NE(warned.err.find("warning: no Eeprom/ConfigData: PDI control (word 0) is 0"), std::string::npos) << warned.err;
    EXPECT_NE(warned.err.find("esc: lan9252-spi"), std::string::npos) << warned.err;
    EXPECT_EQ(tc::tree(out).count("eeprom.bin"), 1u);

    const auto strict_out = dir.path() / "strict";
    const auto strict = tc::esi_gen(dir / "min.yaml", strict_out, {"--only", "sii", "--strict"});
    EXPECT_EQ(strict.exit_code, 1) << strict.err;
    EXPECT_NE(strict.err.find("error: no Eeprom/ConfigData"), std::string::npos) << strict.err;
    EXPECT_TRUE(tc::tree(strict_out).empty());

    // Named ESC: no warning, and the image enables the PDI.
    esi::test::write_text(dir / "esc.yaml", esi::test::read_text(dir / "min.yaml") + "    esc: ax58100-spi\n");
    const auto named_out = dir.path() / "named";
    const auto named = tc::esi_gen(dir / "esc.yaml", named_out, {"--only", "sii", "--strict"});
    ASSERT_EQ(named.exit_code, 0) << named.err;
    const std::string image = tc::tree(named_out).at("eeprom.bin");
    ASSERT_GE(image.size(), 2u);
    EXPECT_EQ(static_cast<unsigned char>(image[0]), 0x05);  // PDI control: SPI
    EXPECT_EQ(image.size(), 2048u);
}

TEST(EsiGenSii, APassiveTerminalGetsNoImage) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "passive.yaml",
                          "vendor: { id: 2, name: Beckhoff }\n"
                          "groups: [{ type: System, name: System }]\n"
                          "devices:\n"
                          "  - { type: EL9011, name: EL9011 End Terminal, physics: \"\" }\n"
                          "  - { type: EK-1, name: Coupler, product_code: 7, revision: 1, esc: et1100-spi }\n");
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(dir / "passive.yaml", out, {"--only", "sii"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto files = tc::tree(out);
    std::size_t images = 0;
    for (const auto& [name, content] : files) {
        std::string lower = name;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        EXPECT_EQ(lower.find("el9011"), std::string::npos) << name;
        images += lower.find("eeprom.bin") != std::string::npos;
    }
    EXPECT_EQ(images, 1u);
}

}  // namespace
