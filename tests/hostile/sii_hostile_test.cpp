// Hostile and broken SII images (issue 6 §2) through the decoder and esi-sii: wrong CRC, a
// category length past the end, endless category chains, sizes that overflow 16 bits, images
// past every size bound. Each gives a fault at its byte offset, exit code 1 (faults) or 2
// (unusable input), bounded memory, and no output file touched.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "esi/sii/build.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"
#include "esi/sii/image_file.hpp"
#include "esi/xml/reader.hpp"
#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

using Bytes = std::vector<std::uint8_t>;
using esi::test::memory_scale;
using esi::test::run_child;

std::string sii_tool() { return esi::test::tool("esi-sii").string(); }

// The sample device's image, not padded: header, categories, end marker.
Bytes sample_image() {
    const esi::ReadResult read = esi::read_esi(esi::test::sample_esi(), "sample.xml");
    const auto& info = read.document->infos.at(0);
    esi::sii::BuildOptions options;
    options.pad_to_eeprom_size = false;
    const esi::sii::BuildResult built = esi::sii::build_image(info, info.devices.at(0), options);
    EXPECT_TRUE(built.ok());
    return built.bytes;
}

// A header with a correct CRC declaring the largest EEPROM (8 MiB), followed by `body`.
Bytes image_with(const Bytes& body, std::uint16_t size_word = 0xFFFF) {
    esi::sii::Image image;
    image.header.size = size_word;
    Bytes bytes = esi::sii::encode_header(image.header);
    bytes.insert(bytes.end(), body.begin(), body.end());
    return bytes;
}

void put_word(Bytes& b, std::size_t at, std::uint16_t value) {
    b[at] = static_cast<std::uint8_t>(value & 0xFF);
    b[at + 1] = static_cast<std::uint8_t>(value >> 8);
}

void push_word(Bytes& b, std::uint16_t value) {
    b.push_back(static_cast<std::uint8_t>(value & 0xFF));
    b.push_back(static_cast<std::uint8_t>(value >> 8));
}

const esi::sii::Fault* find(const esi::sii::DecodedImage& d, std::string_view rule) {
    for (const auto& f : d.faults)
        if (f.rule == rule) return &f;
    return nullptr;
}

void write_bytes(const std::filesystem::path& path, const Bytes& bytes) {
    esi::test::write_text(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace

TEST(HostileSii, WrongCrcIsAnErrorAtTheChecksumWord) {
    Bytes image = sample_image();
    image[0] ^= 0x01;  // the config area changes, the stored CRC does not
    const auto decoded = esi::sii::decode_image(image);
    const auto* crc = find(decoded, "sii-crc");
    ASSERT_NE(crc, nullptr);
    EXPECT_EQ(crc->offset, 0x0Eu);
    esi::test::TempDir dir;
    write_bytes(dir / "crc.bin", image);
    const auto dump = run_child({sii_tool(), "dump", (dir / "crc.bin").string()});
    EXPECT_EQ(dump.exit_code, 1) << dump.err;
    EXPECT_NE(dump.out.find("0x000E"), std::string::npos) << dump.out;
    const auto check = run_child({sii_tool(), "check", (esi::test::source_dir() / "samples/esi/example-digital-io.xml").string(),
                                  (dir / "crc.bin").string()});
    EXPECT_EQ(check.exit_code, 1);
    EXPECT_NE(check.out.find("byte 0x000E: error:"), std::string::npos) << check.out;
}

TEST(HostileSii, CategoryLengthPastTheEndStopsTheWalk) {
    Bytes image = sample_image();
    put_word(image, 0x82, 0xFFFF);  // the first category claims 128 KiB
    const auto decoded = esi::sii::decode_image(image);
    const auto* overrun = find(decoded, "sii-category-overrun");
    ASSERT_NE(overrun, nullptr);
    EXPECT_EQ(overrun->offset, 0x80u);
    EXPECT_EQ(decoded.image.categories.size(), 1u) << "the walk stops at the overrun";
    esi::test::TempDir dir;
    write_bytes(dir / "overrun.bin", image);
    for (const std::string format : {"text", "json"}) {
        const auto dump = run_child({sii_tool(), "dump", "--format", format, (dir / "overrun.bin").string()});
        EXPECT_EQ(dump.exit_code, 1) << format;
        EXPECT_NE(dump.out.find("sii-category-overrun"), std::string::npos) << format;
    }
}

TEST(HostileSii, EndlessCategoryChainIsCutAfterAThousandCategories) {
    // 8 MiB of empty vendor categories (type 1, length 0): two million categories, no end marker.
    Bytes body;
    body.reserve(8u << 20);
    while (body.size() + 4 <= (8u << 20) - 128) {
        push_word(body, 1);
        push_word(body, 0);
    }
    const Bytes image = image_with(body);
    const auto decoded = esi::sii::decode_image(image);
    const auto* cut = find(decoded, "sii-too-many-categories");
    ASSERT_NE(cut, nullptr);
    EXPECT_EQ(cut->offset, 0x80u + 4u * esi::sii::max_categories);
    EXPECT_EQ(decoded.image.categories.size(), esi::sii::max_categories);

    esi::test::TempDir dir;
    write_bytes(dir / "endless.bin", image);
    for (const std::string format : {"text", "json"}) {
        const auto dump = run_child({sii_tool(), "dump", "--format", format, (dir / "endless.bin").string()});
        EXPECT_EQ(dump.exit_code, 1) << format;
        EXPECT_NE(dump.out.find("sii-too-many-categories"), std::string::npos) << format;
        EXPECT_LT(dump.out.size(), 1u << 20) << format;
        EXPECT_LT(dump.max_rss_kb, 64 * 1024 * memory_scale()) << format;
    }
}

TEST(HostileSii, ChainsWithoutEndMarkerOrIntoBlankMemoryEnd) {
    Bytes no_end = image_with({0x01, 0x00, 0x01, 0x00, 0xAA, 0xBB});
    const auto no_end_decoded = esi::sii::decode_image(no_end);  // kept: find() points into it
    const auto* missing = find(no_end_decoded, "sii-no-end-marker");
    ASSERT_NE(missing, nullptr);
    EXPECT_EQ(missing->offset, no_end.size());

    const Bytes zeroed = image_with(Bytes(4096, 0x00));
    const auto decoded = esi::sii::decode_image(zeroed);
    const auto* blank = find(decoded, "sii-chain-blank");
    ASSERT_NE(blank, nullptr);
    EXPECT_EQ(blank->offset, 0x80u);
    EXPECT_LE(decoded.image.categories.size(), esi::sii::blank_category_run_limit);

    // A chain that runs past the EEPROM size word 0x3E declares (a real EEPROM wraps there).
    Bytes past = image_with(Bytes(256, 0x01), 0);  // 128-byte EEPROM, categories after the header
    past.push_back(0xFF);
    past.push_back(0xFF);
    const auto past_decoded = esi::sii::decode_image(past);
    const auto* wrap = find(past_decoded, "sii-chain-past-size");
    ASSERT_NE(wrap, nullptr);
    EXPECT_EQ(wrap->offset, 0x80u);
}

TEST(HostileSii, SixteenMegabytesOfPdoCategoriesAreDecodedOnlyInPart) {
    // PDO categories of 63 PDOs with 255 entries each, as many as fit in 16 MiB.
    Bytes pdo;
    for (const std::uint8_t b : {0x00, 0x1A, 0xFF, 0x03, 0x00, 0x00, 0x00, 0x00}) pdo.push_back(b);
    for (int e = 0; e < 255; ++e)
        for (const std::uint8_t b : {0x00, 0x60, 0x01, 0x00, 0x07, 0x08, 0x00, 0x00}) pdo.push_back(b);
    Bytes body;
    const std::size_t words = pdo.size() * 63 / 2;
    while (body.size() + 4 + 2 * words + 2 + 128 <= esi::sii::max_image_bytes) {
        push_word(body, esi::sii::category::tx_pdo);
        push_word(body, static_cast<std::uint16_t>(words));
        for (int p = 0; p < 63; ++p) body.insert(body.end(), pdo.begin(), pdo.end());
    }
    push_word(body, 0xFFFF);
    const Bytes image = image_with(body);
    const auto decoded = esi::sii::decode_image(image);
    const auto* limit = find(decoded, "sii-decode-limit");
    ASSERT_NE(limit, nullptr);
    EXPECT_EQ(limit->offset, 0x80u) << "the first PDO category alone (126 KiB) passes 64 KiB";
    EXPECT_TRUE(std::holds_alternative<esi::sii::RawData>(decoded.image.categories.at(0).content));
    EXPECT_TRUE(decoded.end_offset) << "the walk still reaches the end marker";

    esi::test::TempDir dir;
    write_bytes(dir / "pdos.bin", image);
    for (const std::string format : {"text", "json"}) {
        const auto dump = run_child({sii_tool(), "dump", "--format", format, (dir / "pdos.bin").string()});
        EXPECT_EQ(dump.exit_code, 1) << format << " (the chain passes the declared 8 MiB)";
        // Bound: 384 MB for the largest image read (16 MiB); it was 3.5 GB before the decode limit.
        EXPECT_LT(dump.max_rss_kb, 384 * 1024 * memory_scale()) << format;
    }
}

TEST(HostileSii, ImagesBeyondTheSizeBoundAreRefused) {
    esi::test::TempDir dir;
    write_bytes(dir / "huge.bin", Bytes(esi::sii::max_image_bytes + 2, 0xFF));
    const auto dump = run_child({sii_tool(), "dump", (dir / "huge.bin").string()});
    EXPECT_EQ(dump.exit_code, 2);
    EXPECT_NE(dump.err.find("larger than any SII EEPROM"), std::string::npos) << dump.err;
    EXPECT_LT(dump.max_rss_kb, 128 * 1024 * memory_scale());

    // Intel HEX whose extended linear address (16-bit upper half) points past 16 MiB.
    esi::test::write_text(dir / "far.hex", ":020000040100F9\n:0100000000FF\n:00000001FF\n");
    const auto far = run_child({sii_tool(), "dump", (dir / "far.hex").string()});
    EXPECT_EQ(far.exit_code, 2);
    EXPECT_NE(far.err.find("beyond 16 MiB"), std::string::npos) << far.err;
}

namespace {

// esi-sii build of a modified sample must fail with exit code 2 and leave -o untouched.
void expect_build_refused(const std::string& esi_text, const std::string& rule, std::uint32_t line) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "device.xml", esi_text);
    esi::test::write_text(dir / "out.bin", "previous image");
    const auto build = run_child({sii_tool(), "build", (dir / "device.xml").string(), "-o", (dir / "out.bin").string()});
    EXPECT_EQ(build.exit_code, 2) << rule << ": " << build.err;
    EXPECT_NE(build.err.find("device.xml:" + std::to_string(line) + ":"), std::string::npos) << build.err;
    EXPECT_NE(build.err.find("[" + rule + "]"), std::string::npos) << build.err;
    EXPECT_EQ(esi::test::read_text(dir / "out.bin"), "previous image");
    EXPECT_EQ(esi::test::snapshot(dir.path()).size(), 2u) << "no temporary file left";
}

}  // namespace

TEST(HostileSii, SizesThatOverflowSixteenBitsAreNotWritten) {
    const std::string sample = esi::test::sample_esi();
    // A vendor category of 128 KiB + 20 bytes: its length word would wrap (it used to be written
    // with the low 16 bits, breaking the category chain after it).
    const std::string big_category = "<Category><CatNo>1000</CatNo><Data>" + std::string(2 * (2 * 0x10000 + 10), 'A') +
                                     "</Data></Category>";
    std::string text = esi::test::replace_once(sample, "<ByteSize>2048</ByteSize>", "<ByteSize>262144</ByteSize>");
    text = esi::test::replace_once(text, "</Eeprom>", big_category + "</Eeprom>");
    expect_build_refused(text, "sii-category-size", esi::test::line_of(text, "<Category><CatNo>1000"));

    text = esi::test::replace_once(sample, "</Eeprom>", "<Category><CatNo>1001</CatNo><DataUINT>65536</DataUINT></Category></Eeprom>");
    expect_build_refused(text, "sii-value-range", esi::test::line_of(text, "<Category><CatNo>1001"));

    text = esi::test::replace_once(sample, "DefaultSize=\"128\"", "DefaultSize=\"65536\"");
    expect_build_refused(text, "sii-value-range", esi::test::line_of(text, "DefaultSize=\"65536\""));

    text = esi::test::replace_once(sample, "<ByteSize>2048</ByteSize>", "<ByteSize>8388736</ByteSize>");
    expect_build_refused(text, "sii-byte-size", esi::test::line_of(text, "<ByteSize>"));
}

TEST(HostileSii, ZeroByteAndDirectoryImages) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "empty.bin", "");
    const auto empty = run_child({sii_tool(), "dump", (dir / "empty.bin").string()});
    EXPECT_EQ(empty.exit_code, 1);
    EXPECT_NE(empty.out.find("sii-truncated"), std::string::npos) << empty.out;
    std::filesystem::create_directories(dir / "image.bin");
    const auto directory = run_child({sii_tool(), "dump", (dir / "image.bin").string()});
    EXPECT_EQ(directory.exit_code, 2);
    EXPECT_NE(directory.err.find("is a directory"), std::string::npos) << directory.err;
    const auto build = run_child({sii_tool(), "build", (dir / "image.bin").string(), "-o", (dir / "out.bin").string()});
    EXPECT_EQ(build.exit_code, 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.bin"));
}
