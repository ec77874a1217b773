// One test per category encoder: byte layout as ETG.1000.6 / ETG.2010 lay it out (offsets
// cross-checked against the real Beckhoff and SOES images in ../shared/corpus/sii).

#include <gtest/gtest.h>

#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"

namespace {

using namespace esi::sii;
using Bytes = std::vector<std::uint8_t>;

TEST(SiiEncode, ConfigCrcIsCrc8Poly07Init0xFF) {
    // Reference values computed independently (bitwise CRC-8, poly 0x07, init 0xFF, no
    // reflection): "123456789" -> 0xFB; the SOES lan9252 image's config area -> 0xC6, the
    // value stored in that real image's word 7.
    const std::string check = "123456789";
    EXPECT_EQ(config_crc(Bytes(check.begin(), check.end())), 0xFB);
    const Bytes soes = {0x80, 0x02, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    EXPECT_EQ(config_crc(soes), 0xC6);
    EXPECT_EQ(config_crc(Bytes{}), 0xFF);
}

TEST(SiiEncode, StringsAreCountedLengthPrefixedAndWordPadded) {
    EXPECT_EQ(encode_strings(Strings{{"AB", "C"}}), (Bytes{2, 2, 'A', 'B', 1, 'C'}));
    EXPECT_EQ(encode_strings(Strings{{"ABC"}}), (Bytes{1, 3, 'A', 'B', 'C', 0}));  // 5 bytes + pad
    EXPECT_EQ(encode_strings(Strings{}), (Bytes{0, 0}));
    EXPECT_EQ(encode_strings(Strings{{""}}), (Bytes{1, 0}));
}

TEST(SiiEncode, GeneralIs32BytesWithPortsAtByte16) {
    General g;
    g.group_idx = 2;
    g.image_idx = 3;
    g.order_idx = 1;
    g.name_idx = 4;
    g.coe_details = 0x23;
    g.foe_details = 1;
    g.eoe_details = 1;
    g.soe_channels = 2;
    g.ds402_channels = 1;
    g.flags = 0x04;
    g.current_on_ebus = -2000;
    g.group_idx_duplicate = 2;
    g.physical_ports = 0x0131;
    g.physical_memory_address = 0x0134;
    const Bytes b = encode_general(g);
    ASSERT_EQ(b.size(), 32u);
    EXPECT_EQ(b[0], 2);
    EXPECT_EQ(b[1], 3);
    EXPECT_EQ(b[2], 1);
    EXPECT_EQ(b[3], 4);
    EXPECT_EQ(b[4], 0);
    EXPECT_EQ(b[5], 0x23);
    EXPECT_EQ(b[6], 1);
    EXPECT_EQ(b[7], 1);
    EXPECT_EQ(b[8], 2);
    EXPECT_EQ(b[9], 1);
    EXPECT_EQ(b[11], 0x04);
    EXPECT_EQ(b[12], 0x30);  // -2000 = 0xF830, as in the real EK1100 image
    EXPECT_EQ(b[13], 0xF8);
    EXPECT_EQ(b[14], 2);
    EXPECT_EQ(b[16], 0x31);  // YKY -> 0x0131, as in the real EK1100 image
    EXPECT_EQ(b[17], 0x01);
    EXPECT_EQ(b[18], 0x34);
    EXPECT_EQ(b[19], 0x01);
    for (std::size_t i = 20; i < 32; ++i) EXPECT_EQ(b[i], 0) << i;
}

TEST(SiiEncode, FmmusAreOneBytePaddedWithNotUsed) {
    EXPECT_EQ(encode_fmmus(Fmmus{{1, 2, 3}}), (Bytes{1, 2, 3, 0xFF}));
    EXPECT_EQ(encode_fmmus(Fmmus{{1, 2}}), (Bytes{1, 2}));
    EXPECT_EQ(encode_fmmus(Fmmus{{1}}, 0x00), (Bytes{1, 0}));
}

TEST(SiiEncode, SyncManagerRecordsAreEightBytes) {
    SyncManagers s;
    s.items.push_back({0x1000, 128, 0x26, 0, 0x01, 1});
    s.items.push_back({0x0998, 0, 0x00, 0, 0x04, 4});
    EXPECT_EQ(encode_sync_managers(s), (Bytes{0x00, 0x10, 0x80, 0x00, 0x26, 0x00, 0x01, 0x01,  //
                                              0x98, 0x09, 0x00, 0x00, 0x00, 0x00, 0x04, 0x04}));
}

TEST(SiiEncode, PdoHeaderAndEntriesAreEightBytesEach) {
    PdoRecord pdo;
    pdo.index = 0x1600;
    pdo.sync_manager = 2;
    pdo.dc_sync = 0;
    pdo.name_idx = 5;
    pdo.flags = 0x0011;
    pdo.entries.push_back({0x7000, 1, 6, 0x01, 1, 0});
    pdo.entries.push_back({0x0000, 0, 0, 0x00, 7, 0});
    // The EL2004 image holds 00 16 01 00 00 05 11 00 | 00 70 01 06 01 01 00 00 for one such PDO.
    EXPECT_EQ(encode_pdos(Pdos{{pdo}}), (Bytes{0x00, 0x16, 0x02, 0x02, 0x00, 0x05, 0x11, 0x00,  //
                                               0x00, 0x70, 0x01, 0x06, 0x01, 0x01, 0x00, 0x00,  //
                                               0x00, 0x00, 0x00, 0x00, 0x00, 0x07, 0x00, 0x00}));
}

TEST(SiiEncode, DcOpModeIs24BytesEtg2010Table12) {
    DcOpModeRecord m;
    m.cycle_time0 = 1000000;
    m.shift_time0 = static_cast<std::uint32_t>(-2500);
    m.shift_time1 = 7000;
    m.sync1_cycle_factor = -1;
    m.assign_activate = 0x0730;
    m.sync0_cycle_factor = -8;
    m.name_idx = 5;
    m.desc_idx = 6;
    const Bytes b = encode_dc(DcOpModes{{m}});
    ASSERT_EQ(b.size(), 24u);
    EXPECT_EQ((Bytes{b.begin(), b.begin() + 4}), (Bytes{0x40, 0x42, 0x0F, 0x00}));
    EXPECT_EQ((Bytes{b.begin() + 4, b.begin() + 8}), (Bytes{0x3C, 0xF6, 0xFF, 0xFF}));
    EXPECT_EQ((Bytes{b.begin() + 8, b.begin() + 12}), (Bytes{0x58, 0x1B, 0x00, 0x00}));
    // The EL2262 image holds ff ff 30 07 f8 ff 06 for factor -1, 0x0730, factor -8, name 6.
    EXPECT_EQ((Bytes{b.begin() + 12, b.begin() + 20}), (Bytes{0xFF, 0xFF, 0x30, 0x07, 0xF8, 0xFF, 5, 6}));
    EXPECT_EQ((Bytes{b.begin() + 20, b.end()}), (Bytes{0, 0, 0, 0}));
}

TEST(SiiEncode, RawCategoriesArePaddedToAWord) {
    EXPECT_EQ(encode_content(RawData{{1, 2, 3}}), (Bytes{1, 2, 3, 0}));
    EXPECT_EQ(encode_content(RawData{}), Bytes{});
}

TEST(SiiEncode, HeaderPutsIdentityMailboxAndSizeAtTheirWords) {
    Header h;
    h.config_data = {0x80, 0x02};
    h.vendor_id = 0x1337;
    h.product_code = 0x04D2;
    h.revision_no = 0x00020001;
    h.serial_no = 0xAABBCCDD;
    h.bootstrap_receive_offset = 0x1000;
    h.bootstrap_send_size = 0x0080;
    h.standard_receive_offset = 0x1000;
    h.standard_receive_size = 128;
    h.standard_send_offset = 0x1080;
    h.standard_send_size = 128;
    h.mailbox_protocols = 0x000C;
    h.size = 1;
    const Bytes b = encode_header(h);
    ASSERT_EQ(b.size(), 128u);
    auto word = [&](std::size_t w) { return b[2 * w] | (b[2 * w + 1] << 8); };
    EXPECT_EQ(word(0x07), 0x00C6);
    EXPECT_EQ(word(0x08), 0x1337);
    EXPECT_EQ(word(0x0A), 0x04D2);
    EXPECT_EQ(word(0x0C), 0x0001);
    EXPECT_EQ(word(0x0D), 0x0002);
    EXPECT_EQ(word(0x0E), 0xCCDD);
    EXPECT_EQ(word(0x14), 0x1000);
    EXPECT_EQ(word(0x17), 0x0080);
    EXPECT_EQ(word(0x18), 0x1000);
    EXPECT_EQ(word(0x19), 128);
    EXPECT_EQ(word(0x1A), 0x1080);
    EXPECT_EQ(word(0x1C), 0x000C);
    EXPECT_EQ(word(0x3E), 1);
    EXPECT_EQ(word(0x3F), 1);
    h.checksum = 0x88A4;
    EXPECT_EQ(encode_header(h, false)[14], 0xA4);  // written as it is when not computed
}

TEST(SiiEncode, ImageEndsWithTheEndMarkerAndIsPaddedWithErasedBytes) {
    Image image;
    image.categories.push_back({category::strings, Strings{{"X"}}, 0, 0});
    const Bytes b = encode_image(image, 256);
    ASSERT_EQ(b.size(), 256u);
    EXPECT_EQ(encoded_size(image), 128u + 4u + 4u + 2u);
    EXPECT_EQ(b[128], 10);
    EXPECT_EQ(b[130], 2);  // length in words
    EXPECT_EQ(b[136], 0xFF);
    EXPECT_EQ(b[137], 0xFF);
    EXPECT_EQ(b[138], 0xFF);  // padding
    EXPECT_EQ(encode_image(image).size(), 138u);
}

TEST(SiiEncode, EveryEncoderRoundTripsThroughTheDecoder) {
    Image image;
    image.header.vendor_id = 2;
    image.header.size = 1;
    image.header.standard_receive_offset = 0x1000;
    image.header.standard_receive_size = 128;
    General g;
    g.name_idx = 1;
    g.physical_ports = 0x33;
    PdoRecord pdo{0x1A00, 3, 0, 1, 0x0010, {{0x6000, 1, 1, 0x07, 32, 0}}};
    DcOpModeRecord dc;
    dc.assign_activate = 0x0300;
    dc.sync0_cycle_factor = 1;
    image.categories = {{category::strings, Strings{{"name"}}, 0, 0},
                        {category::general, g, 0, 0},
                        {category::fmmu, Fmmus{{1, 2, 3}}, 0, 0},
                        {category::sync_manager, SyncManagers{{{0x1000, 128, 0x26, 0, 1, 1}}}, 0, 0},
                        {category::tx_pdo, Pdos{{pdo}}, 0, 0},
                        {category::dc, DcOpModes{{dc}}, 0, 0},
                        {0x0800, RawData{{9, 8}}, 0, 0}};
    image.header.config_data[0] = 0x05;  // SPI: a mailbox behind a PDI that is off is a fault (sii-pdi-off)
    const DecodedImage d = decode_image(encode_image(image, 256));
    EXPECT_TRUE(d.faults.empty()) << d.faults.front().message;
    ASSERT_EQ(d.image.categories.size(), image.categories.size());
    EXPECT_EQ(*d.image.strings(), (Strings{{"name"}}));
    EXPECT_EQ(*d.image.general(), g);
    EXPECT_EQ(d.image.fmmus()->usages, (std::vector<std::uint8_t>{1, 2, 3, 0xFF}));
    EXPECT_EQ(*d.image.sync_managers(), (SyncManagers{{{0x1000, 128, 0x26, 0, 1, 1}}}));
    EXPECT_EQ(*d.image.pdos(category::tx_pdo), (Pdos{{pdo}}));
    EXPECT_EQ(*d.image.dc(), (DcOpModes{{dc}}));
    EXPECT_EQ(std::get<RawData>(d.image.categories.back().content).bytes, (Bytes{9, 8}));
    EXPECT_EQ(d.image.categories[1].offset, 128u + 4u + 6u);  // after the 6-byte Strings payload
}

}  // namespace
