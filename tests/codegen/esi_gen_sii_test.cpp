// esi-gen writes the SII EEPROM image next to the ESI and the code (issue 5 §1), so that image,
// ESI and firmware tables come from one source. The image must be the one `esi-sii build` makes
// from the same source, and must check clean against the ESI written in the same run.

#include <gtest/gtest.h>

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
