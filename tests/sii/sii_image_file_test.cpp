// The three image file formats: raw binary, Intel HEX (round trip through the parser, extended
// addresses past 64 KiB, every malformed record refused) and the C array.

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "esi/sii/image_file.hpp"

namespace {

using namespace esi::sii;
using Bytes = std::vector<std::uint8_t>;

Bytes pattern(std::size_t n) {
    Bytes b(n);
    for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::uint8_t>((i * 7 + 3) & 0xFF);
    return b;
}

TEST(SiiImageFile, FormatNames) {
    ImageFormat f{};
    EXPECT_TRUE(parse_image_format("bin", f));
    EXPECT_EQ(f, ImageFormat::bin);
    EXPECT_TRUE(parse_image_format("hex", f));
    EXPECT_EQ(f, ImageFormat::hex);
    EXPECT_TRUE(parse_image_format("c", f));
    EXPECT_EQ(f, ImageFormat::c);
    EXPECT_FALSE(parse_image_format("srec", f));
}

TEST(SiiImageFile, BinaryIsTheBytesThemselves) {
    const Bytes b = pattern(300);
    const std::string out = format_image(b, ImageFormat::bin);
    EXPECT_EQ(Bytes(out.begin(), out.end()), b);
}

TEST(SiiImageFile, IntelHexRecordsAndChecksums) {
    const Bytes b = {0x80, 0x02, 0x00, 0x00};
    // :04 0000 00 80020000 -> sum 04+00+00+00+80+02 = 0x86 -> checksum 0x7A
    EXPECT_EQ(to_intel_hex(b), ":04000000800200007A\n:00000001FF\n");
    const std::string hex = to_intel_hex(pattern(40));
    EXPECT_EQ(std::count(hex.begin(), hex.end(), '\n'), 4);  // 16 + 16 + 8 bytes + EOF
    EXPECT_EQ(hex.substr(0, 9), ":10000000");
    EXPECT_NE(hex.find("\n:08002000"), std::string::npos);
}

TEST(SiiImageFile, IntelHexRoundTripsIncludingPast64KiB) {
    for (const std::size_t size : {std::size_t{0}, std::size_t{1}, std::size_t{2048}, std::size_t{70000}}) {
        SCOPED_TRACE(size);
        const Bytes b = pattern(size);
        const std::string hex = to_intel_hex(b);
        if (size > 65536) {
            EXPECT_NE(hex.find(":020000040001F9"), std::string::npos);
        }
        const HexParseResult parsed = parse_intel_hex(hex);
        ASSERT_TRUE(parsed.bytes.has_value()) << parsed.error;
        EXPECT_EQ(*parsed.bytes, b);
    }
}

TEST(SiiImageFile, IntelHexAcceptsCrLfAndLowerCase) {
    const HexParseResult r = parse_intel_hex(":04000000800200007a\r\n:00000001ff\r\n");
    ASSERT_TRUE(r.bytes.has_value()) << r.error;
    EXPECT_EQ(*r.bytes, (Bytes{0x80, 0x02, 0x00, 0x00}));
}

TEST(SiiImageFile, MalformedIntelHexIsRefusedWithItsLine) {
    const std::pair<std::string, std::size_t> bad[] = {
        {":04000000800200007B\n:00000001FF\n", 1},      // checksum
        {":0400000080020000\n:00000001FF\n", 1},        // record too short for its count
        {":04000000800200007A\n", 0},                   // no EOF record
        {":04000000800200007A\nxyz\n:00000001FF\n", 2},  // not a record
        {":0400000080G200007A\n:00000001FF\n", 1},      // bad digit
        {":00000001FF\n:04000000800200007A\n", 2},      // data after EOF
        {":020000040100F9\n:04000000800200007A\n:00000001FF\n", 2},  // beyond 16 MiB
    };
    for (const auto& [text, line] : bad) {
        SCOPED_TRACE(text);
        const HexParseResult r = parse_intel_hex(text);
        EXPECT_FALSE(r.bytes.has_value());
        EXPECT_FALSE(r.error.empty());
        EXPECT_EQ(r.line, line);
    }
}

TEST(SiiImageFile, LoadImageTellsHexFromBinary) {
    const Bytes b = pattern(64);
    const LoadedImage from_hex = load_image(to_intel_hex(b));
    ASSERT_TRUE(from_hex.bytes.has_value());
    EXPECT_TRUE(from_hex.was_hex);
    EXPECT_EQ(*from_hex.bytes, b);
    const std::string raw(b.begin(), b.end());
    const LoadedImage from_bin = load_image(raw);
    EXPECT_FALSE(from_bin.was_hex);
    EXPECT_EQ(*from_bin.bytes, b);
    EXPECT_FALSE(load_image(":zz\n").bytes.has_value());
    EXPECT_FALSE(load_image_file("/nonexistent/image.bin").bytes.has_value());
}

TEST(SiiImageFile, CArrayHoldsEveryByteInOrder) {
    const Bytes b = pattern(37);
    const std::string c = to_c_array(b, "my_eeprom", "EL2004 rev 0x00100000");
    EXPECT_NE(c.find("EL2004 rev 0x00100000"), std::string::npos);
    EXPECT_NE(c.find("const uint8_t my_eeprom[37] = {"), std::string::npos);
    EXPECT_NE(c.find("const size_t my_eeprom_size = sizeof my_eeprom;"), std::string::npos);
    Bytes parsed;
    const std::regex byte_re("0x([0-9A-F]{2}),");
    for (auto it = std::sregex_iterator(c.begin(), c.end(), byte_re); it != std::sregex_iterator(); ++it)
        parsed.push_back(static_cast<std::uint8_t>(std::stoul((*it)[1].str(), nullptr, 16)));
    EXPECT_EQ(parsed, b);
    EXPECT_EQ(format_image(b, ImageFormat::c), to_c_array(b));
}

}  // namespace
