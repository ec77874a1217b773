// Every corruption the decoder must catch, each at the byte offset where it sits, and hostile
// input that must neither crash nor hang (the decoder runs under ASan/UBSan in CI).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"
#include "esi/sii/render.hpp"

namespace {

using namespace esi::sii;
using Bytes = std::vector<std::uint8_t>;

// A valid image: Strings at 0x80 (6-byte payload), General at 0x8A, FMMU at 0xAE, SyncM at 0xB4,
// RxPDO at 0xC8, DC at 0xDC, end marker at 0xF8; EEPROM size 256 bytes.
Image valid_image() {
    Image image;
    image.header.config_data = {0x80, 0x02};
    image.header.vendor_id = 0x1337;
    image.header.product_code = 0x1234;
    image.header.standard_receive_offset = 0x1000;
    image.header.standard_receive_size = 128;
    image.header.standard_send_offset = 0x1080;
    image.header.standard_send_size = 128;
    image.header.mailbox_protocols = 0x0004;
    image.header.size = 1;
    General g;
    g.name_idx = 1;
    image.categories = {{category::strings, Strings{{"dev"}}, 0, 0},
                        {category::general, g, 0, 0},
                        {category::fmmu, Fmmus{{1, 2}}, 0, 0},
                        {category::sync_manager, SyncManagers{{{0x1000, 128, 0x26, 0, 1, 1}, {0x1080, 128, 0x22, 0, 1, 2}}}, 0, 0},
                        {category::rx_pdo, Pdos{{{0x1600, 2, 0, 1, 0, {{0x7000, 1, 1, 5, 8, 0}}}}}, 0, 0},
                        {category::dc, DcOpModes{{DcOpModeRecord{}}}, 0, 0}};
    return image;
}

Bytes valid_bytes(std::size_t pad = 256) { return encode_image(valid_image(), pad); }

constexpr std::size_t general_at = 0x8A;
constexpr std::size_t sync_manager_at = 0xB4;
constexpr std::size_t rx_pdo_at = 0xC8;
constexpr std::size_t dc_at = 0xDC;
constexpr std::size_t end_at = 0xF8;

void put_word(Bytes& b, std::size_t offset, std::uint16_t value) {
    b[offset] = static_cast<std::uint8_t>(value & 0xFF);
    b[offset + 1] = static_cast<std::uint8_t>(value >> 8);
}

const Fault* find(const DecodedImage& d, const std::string& rule) {
    for (const auto& f : d.faults)
        if (f.rule == rule) return &f;
    return nullptr;
}

TEST(SiiDecode, AValidImageHasNoFaults) {
    const DecodedImage d = decode_image(valid_bytes());
    EXPECT_TRUE(d.faults.empty()) << d.faults.front().message;
    EXPECT_TRUE(d.crc_ok);
    ASSERT_TRUE(d.end_offset.has_value());
    EXPECT_EQ(*d.end_offset, end_at);
    ASSERT_EQ(d.image.categories.size(), 6u);
    EXPECT_EQ(d.image.categories[1].offset, general_at);
    EXPECT_EQ(d.image.categories[3].offset, sync_manager_at);
    EXPECT_EQ(d.image.categories[4].offset, rx_pdo_at);
    EXPECT_EQ(d.image.categories[5].offset, dc_at);
}

TEST(SiiDecode, BadCrcIsReportedAtByte14) {
    Bytes b = valid_bytes();
    b[2] ^= 0x01;  // a config byte changes, the checksum does not
    const DecodedImage d = decode_image(b);
    const Fault* f = find(d, "sii-crc");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, esi::Severity::error);
    EXPECT_EQ(f->offset, 0x0Eu);
    EXPECT_FALSE(d.crc_ok);
}

TEST(SiiDecode, ChecksumDisabledMarkerIsAWarning) {
    Bytes b = valid_bytes();
    put_word(b, 0x0E, 0x88A4);
    const DecodedImage d = decode_image(b);
    ASSERT_NE(find(d, "sii-crc-disabled"), nullptr);
    EXPECT_EQ(find(d, "sii-crc-disabled")->severity, esi::Severity::warning);
    EXPECT_EQ(find(d, "sii-crc"), nullptr);
}

TEST(SiiDecode, CategoryPastTheEndIsReportedAtItsHeader) {
    Bytes b = valid_bytes(0);
    put_word(b, dc_at + 2, 0x0400);  // the DC category claims 1024 words
    const DecodedImage d = decode_image(b);
    const Fault* f = find(d, "sii-category-overrun");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->offset, dc_at);
    EXPECT_FALSE(d.end_offset.has_value());
    EXPECT_EQ(d.image.categories.size(), 6u);  // the overrunning one kept as raw bytes for the dump
}

TEST(SiiDecode, MissingEndMarkerIsReportedAtTheEndOfTheImage) {
    Bytes b = valid_bytes(0);
    b.resize(b.size() - 2);  // drop the 0xFFFF
    const DecodedImage d = decode_image(b);
    const Fault* f = find(d, "sii-no-end-marker");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->offset, b.size());
    EXPECT_EQ(d.image.categories.size(), 6u);
}

TEST(SiiDecode, EndMarkerWithoutLengthWordIsEnough) {
    // The xmc4300 SOES image ends with the end marker's type word as its last two bytes.
    const Bytes b = valid_bytes(0);
    ASSERT_EQ(b.size(), end_at + 2);
    const DecodedImage d = decode_image(b);
    EXPECT_TRUE(d.faults.empty());
}

TEST(SiiDecode, TruncatedFilesAreReportedNotRead) {
    for (const std::size_t size : {0u, 1u, 14u, 15u, 100u, 127u}) {
        SCOPED_TRACE(size);
        Bytes b = valid_bytes();
        b.resize(size);
        const DecodedImage d = decode_image(b);
        const Fault* f = find(d, "sii-truncated");
        ASSERT_NE(f, nullptr);
        EXPECT_EQ(f->offset, size);
        EXPECT_FALSE(d.header_complete);
        EXPECT_TRUE(d.image.categories.empty());
        EXPECT_FALSE(render_dump_text(d, "t.bin").empty());
    }
    Bytes header_only = valid_bytes();
    header_only.resize(128);
    const DecodedImage d = decode_image(header_only);
    EXPECT_TRUE(d.header_complete);
    ASSERT_NE(find(d, "sii-no-end-marker"), nullptr);  // IgH: at least 0x41 words
    EXPECT_EQ(find(d, "sii-no-end-marker")->offset, 128u);
}

TEST(SiiDecode, CategoryHeaderCutOffByTheEnd) {
    Bytes b = valid_bytes(0);
    b.resize(dc_at + 2);  // only the DC type word is left
    const DecodedImage d = decode_image(b);
    ASSERT_NE(find(d, "sii-category-truncated"), nullptr);
    EXPECT_EQ(find(d, "sii-category-truncated")->offset, dc_at);
}

TEST(SiiDecode, OddLengthIsAWarning) {
    Bytes b = valid_bytes();
    b.push_back(0xFF);
    const DecodedImage d = decode_image(b);
    ASSERT_NE(find(d, "sii-odd-length"), nullptr);
    EXPECT_EQ(find(d, "sii-odd-length")->severity, esi::Severity::warning);
}

TEST(SiiDecode, ChainBeyondTheDeclaredSizeStopsTheWalk) {
    Bytes b = valid_bytes(512);
    put_word(b, 0x7C, 0);  // declares 128 bytes: the categories cannot be there
    const DecodedImage d = decode_image(b);
    const Fault* f = find(d, "sii-chain-past-size");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->offset, 0x80u);
    ASSERT_NE(find(d, "sii-larger-than-size"), nullptr);
}

TEST(SiiDecode, BlankMemoryEndsTheWalkInsteadOfListingEmptyCategories) {
    Bytes b = valid_bytes(0);
    b.resize(0x80);
    b.resize(64 * 1024, 0x00);  // zeroed EEPROM after the header
    put_word(b, 0x7C, 0x01FF);  // 64 KiB declared
    const DecodedImage d = decode_image(b);
    const Fault* f = find(d, "sii-chain-blank");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->offset, 0x80u);
    EXPECT_LT(d.image.categories.size(), blank_category_run_limit);
}

TEST(SiiDecode, StringRunningPastItsCategory) {
    Bytes b = valid_bytes();
    b[0x85] = 200;  // "dev" claims 200 bytes
    const DecodedImage d = decode_image(b);
    const Fault* f = find(d, "sii-strings-overrun");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->offset, 0x85u);
}

TEST(SiiDecode, GeneralCategoryOfTheWrongSize) {
    Image image = valid_image();
    image.categories[1].content = RawData{Bytes(30, 0)};
    const DecodedImage d = decode_image(encode_image(image, 256));
    ASSERT_NE(find(d, "sii-general-size"), nullptr);
    EXPECT_EQ(find(d, "sii-general-size")->offset, general_at + 4);
    EXPECT_EQ(d.image.general(), nullptr);
}

TEST(SiiDecode, SyncManagerAndDcCategoriesMustHoldWholeRecords) {
    Image image = valid_image();
    image.categories[3].content = RawData{Bytes(10, 0)};
    image.categories[5].content = RawData{Bytes(26, 0)};
    const DecodedImage d = decode_image(encode_image(image, 256));
    ASSERT_NE(find(d, "sii-sync-manager-size"), nullptr);
    ASSERT_NE(find(d, "sii-dc-size"), nullptr);
    EXPECT_EQ(d.image.sync_managers()->items.size(), 1u);
    EXPECT_EQ(d.image.dc()->items.size(), 1u);
}

TEST(SiiDecode, PdoEntriesRunningPastTheCategory) {
    Bytes b = valid_bytes();
    b[rx_pdo_at + 4 + 2] = 9;  // the RxPDO claims 9 entries, holds 1
    const DecodedImage d = decode_image(b);
    const Fault* f = find(d, "sii-pdo-overrun");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->offset, rx_pdo_at + 4);
}

TEST(SiiDecode, StringIndexPastTheStringsCategory) {
    Bytes b = valid_bytes();
    b[general_at + 4 + 3] = 7;  // General name index 7, one string present
    const DecodedImage d = decode_image(b);
    const Fault* f = find(d, "sii-string-index");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->offset, general_at + 4 + 3);
    EXPECT_EQ(f->severity, esi::Severity::warning);
}

TEST(SiiDecode, DuplicateCategoryAndMissingGeneral) {
    Image image = valid_image();
    image.categories[1] = {category::strings, Strings{{"x"}}, 0, 0};
    const DecodedImage d = decode_image(encode_image(image, 256));
    ASSERT_NE(find(d, "sii-duplicate-category"), nullptr);
    EXPECT_EQ(find(d, "sii-duplicate-category")->offset, general_at);
    ASSERT_NE(find(d, "sii-no-general"), nullptr);
}

TEST(SiiDecode, MailboxWordsThatContradictTheSyncMCategory) {
    Image image = valid_image();
    image.header.standard_send_size = 64;
    const DecodedImage d = decode_image(encode_image(image, 256));
    const Fault* f = find(d, "sii-mailbox-sm-mismatch");
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->offset, sync_manager_at + 4 + 8);  // SyncM record 1
}

TEST(SiiDecode, VersionOtherThanOne) {
    Bytes b = valid_bytes();
    put_word(b, 0x7E, 2);
    ASSERT_NE(find(decode_image(b), "sii-version"), nullptr);
}

TEST(SiiDecode, FaultsAreOrderedByOffsetAndConvertToDiagnostics) {
    Bytes b = valid_bytes();
    b[2] ^= 1;
    put_word(b, 0x7E, 2);
    const DecodedImage d = decode_image(b);
    ASSERT_GE(d.faults.size(), 2u);
    for (std::size_t i = 1; i < d.faults.size(); ++i) EXPECT_LE(d.faults[i - 1].offset, d.faults[i].offset);
    const esi::Diagnostics diags = to_diagnostics(d.faults, "x.bin");
    ASSERT_EQ(diags.size(), d.faults.size());
    EXPECT_EQ(diags.items().front().path, "x.bin");
    EXPECT_EQ(diags.items().front().message.rfind("byte 0x000E: ", 0), 0u);
}

TEST(SiiDecode, HostileInputNeitherCrashesNorHangs) {
    std::mt19937 random(20240521);
    const Bytes base = valid_bytes();
    std::size_t decoded = 0;
    for (int round = 0; round < 3000; ++round) {
        Bytes b = base;
        if (round % 3 == 0) {
            // Pure noise of random length.
            b.resize(random() % 600);
            for (auto& x : b) x = static_cast<std::uint8_t>(random());
        } else {
            // A valid image with a few bytes changed, often in the category headers.
            const int flips = 1 + static_cast<int>(random() % 8);
            for (int i = 0; i < flips; ++i) {
                const std::size_t at = round % 2 ? 0x80 + random() % 0x80 : random() % b.size();
                b[at] = static_cast<std::uint8_t>(random());
            }
            if (round % 5 == 0) b.resize(random() % b.size());
        }
        const DecodedImage d = decode_image(b);
        ++decoded;
        EXPECT_LE(d.image.categories.size(), b.size() / 4 + 1);
        const std::string text = render_dump_text(d, "fuzz.bin");
        const std::string json = render_dump_json(d, "fuzz.bin");
        EXPECT_FALSE(text.empty());
        EXPECT_TRUE(nlohmann::json::accept(json));
    }
    EXPECT_EQ(decoded, 3000u);
}

TEST(SiiDecode, LengthWordsOfAllOnesNeverOverflow) {
    Bytes b = valid_bytes();
    for (std::size_t at = 0x80; at + 4 <= b.size(); at += 4) put_word(b, at + 2, 0xFFFF);
    const DecodedImage d = decode_image(b);
    ASSERT_NE(find(d, "sii-category-overrun"), nullptr);
    EXPECT_EQ(find(d, "sii-category-overrun")->offset, 0x80u);
}

}  // namespace
