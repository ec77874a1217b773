// esi-sii check: an image built from an ESI checks clean; each field the ETG conformance
// tool's ESI tests compare, changed in the image, gives its own mismatch on the ESI element with
// a note naming the image offset.

#include <gtest/gtest.h>

#include <functional>

#include "esi/sii/check.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"
#include "fixture.hpp"

namespace {

using namespace esi::sii;
using esi::Severity;

struct Checked {
    esi::Diagnostics diagnostics;
    bool has(const std::string& rule, Severity severity = Severity::error) const {
        return esi::test::has_rule(diagnostics, rule, severity);
    }
    const esi::Diagnostic* first(const std::string& rule) const {
        for (const auto& d : diagnostics)
            if (d.rule == rule) return &d;
        return nullptr;
    }
};

// Builds the fixture, lets `edit` change the decoded image, re-encodes (CRC recomputed) and checks.
Checked check_edited(const std::function<void(Image&)>& edit, const std::string& xml = esi::test::fixture_xml()) {
    const esi::test::Fixture f = esi::test::load_fixture(xml);
    const BuildResult built = build_image(f.info(), f.device(), {}, "fixture.xml");
    EXPECT_TRUE(built.ok());
    DecodedImage decoded = decode_image(built.bytes);
    edit(decoded.image);
    const DecodedImage again = decode_image(encode_image(decoded.image, 2048));
    return {check_image(f.info(), f.device(), again, "fixture.xml", "image.bin")};
}

template <typename T>
T& content(Image& image, std::uint16_t type) {
    for (auto& c : image.categories)
        if (c.type == type) return std::get<T>(c.content);
    throw std::runtime_error("no such category");
}

TEST(SiiCheck, AnImageBuiltFromTheEsiChecksClean) {
    const Checked c = check_edited([](Image&) {});
    EXPECT_TRUE(c.diagnostics.empty()) << c.diagnostics.items().front().message;
}

TEST(SiiCheck, IdentityMismatchesAreCtt21To23) {
    const Checked c = check_edited([](Image& i) {
        i.header.vendor_id = 1;
        i.header.product_code = 2;
        i.header.revision_no = 3;
    });
    ASSERT_TRUE(c.has("sii-vendor-id"));
    ASSERT_TRUE(c.has("sii-product-code"));
    ASSERT_TRUE(c.has("sii-revision"));
    const esi::Diagnostic* d = c.first("sii-product-code");
    EXPECT_EQ(d->path, "fixture.xml");
    EXPECT_TRUE(d->pos.known());
    ASSERT_EQ(d->notes.size(), 1u);
    EXPECT_EQ(d->notes[0].path, "image.bin");
    EXPECT_EQ(d->notes[0].message, "image byte 0x0014 (word 0x0A)");
}

TEST(SiiCheck, MailboxProtocolsAndMailboxWords) {
    const Checked c = check_edited([](Image& i) {
        i.header.mailbox_protocols = mailbox_protocol::coe;
        i.header.standard_send_size = 64;
        i.header.bootstrap_receive_size = 0x100;
    });
    EXPECT_TRUE(c.has("sii-mailbox-protocols"));
    EXPECT_TRUE(c.has("sii-standard-mailbox"));
    EXPECT_TRUE(c.has("sii-boot-strap"));
    EXPECT_NE(c.first("sii-mailbox-protocols")->message.find("EoE CoE FoE"), std::string::npos);
}

TEST(SiiCheck, EepromSizeAndConfigData) {
    const Checked c = check_edited([](Image& i) {
        i.header.size = 7;
        i.header.config_data[2] = 0x99;
    });
    EXPECT_TRUE(c.has("sii-eeprom-size"));
    ASSERT_TRUE(c.has("sii-config-data"));
    EXPECT_EQ(c.first("sii-config-data")->notes[0].message, "image byte 0x0002 (word 0x01)");
}

TEST(SiiCheck, GeneralCategoryFields) {
    const Checked c = check_edited([](Image& i) {
        General& g = content<General>(i, category::general);
        g.coe_details = 0x01;
        g.foe_details = 0;
        g.eoe_details = 0;
        g.flags = 0;
        g.current_on_ebus = 100;
        g.physical_ports = 0x0111;
        g.name_idx = g.order_idx;
    });
    EXPECT_TRUE(c.has("sii-general-coe"));
    EXPECT_TRUE(c.has("sii-general-foe"));
    EXPECT_TRUE(c.has("sii-general-eoe"));
    EXPECT_TRUE(c.has("sii-general-flags"));
    EXPECT_TRUE(c.has("sii-ebus-current"));
    ASSERT_TRUE(c.has("sii-physical-ports"));
    EXPECT_NE(c.first("sii-physical-ports")->message.find("port 2"), std::string::npos);
    EXPECT_TRUE(c.has("sii-general-strings", Severity::warning));
}

TEST(SiiCheck, NamesInAnotherLanguageStillMatch) {
    const esi::test::Fixture f = esi::test::load_fixture(esi::test::fixture_xml());
    BuildOptions german;
    german.name_lcid = 1031;
    const DecodedImage d = decode_image(build_image(f.info(), f.device(), german, "fixture.xml").bytes);
    EXPECT_TRUE(check_image(f.info(), f.device(), d, "fixture.xml", "image.bin").empty());
}

TEST(SiiCheck, MissingGeneralCategory) {
    const Checked c = check_edited([](Image& i) { std::erase_if(i.categories, [](const Category& x) { return x.type == category::general; }); });
    EXPECT_TRUE(c.has("sii-general-missing"));
}

TEST(SiiCheck, FmmuAndSyncManagerCategories) {
    const Checked c = check_edited([](Image& i) {
        content<Fmmus>(i, category::fmmu).usages = {2, 1, 3};
        auto& sms = content<SyncManagers>(i, category::sync_manager).items;
        sms[2].control = 0x24;
        sms[3].enable = 0x01;
    });
    EXPECT_TRUE(c.has("sii-fmmu"));
    ASSERT_TRUE(c.has("sii-sync-manager"));
    std::size_t sm_mismatches = 0;
    for (const auto& d : c.diagnostics) sm_mismatches += d.rule == "sii-sync-manager";
    EXPECT_EQ(sm_mismatches, 2u);
    const Checked fewer = check_edited([](Image& i) { content<SyncManagers>(i, category::sync_manager).items.pop_back(); });
    EXPECT_TRUE(fewer.has("sii-sync-manager"));
}

TEST(SiiCheck, PdoCategoriesWherePresent) {
    const Checked c = check_edited([](Image& i) {
        auto& rx = content<Pdos>(i, category::rx_pdo).items;
        rx[0].entries[0].bit_len = 8;
        auto& tx = content<Pdos>(i, category::tx_pdo).items;
        tx.pop_back();                              // 0x1A01 missing: it has no Sm, an info
        tx.push_back(PdoRecord{0x1A7F, 3, 0, 0, 0, {}});  // not in the ESI
    });
    std::size_t pdo = 0;
    for (const auto& d : c.diagnostics) pdo += d.rule == "sii-pdo" && d.severity == Severity::error;
    EXPECT_EQ(pdo, 2u);
    EXPECT_TRUE(c.has("sii-pdo", Severity::info));
    // A PDO of the default assignment (0x1A00, Sm 3) missing is an error.
    const Checked default_missing = check_edited([](Image& i) {
        auto& tx = content<Pdos>(i, category::tx_pdo).items;
        tx.erase(tx.begin());
    });
    EXPECT_TRUE(default_missing.has("sii-pdo", Severity::error));
    const Checked absent = check_edited([](Image& i) {
        std::erase_if(i.categories, [](const Category& x) { return x.type == category::tx_pdo || x.type == category::rx_pdo; });
    });
    EXPECT_FALSE(absent.diagnostics.has_errors());  // optional categories
    EXPECT_TRUE(absent.has("sii-pdo", Severity::info));
}

TEST(SiiCheck, DcCategoryWherePresent) {
    const Checked c = check_edited([](Image& i) { content<DcOpModes>(i, category::dc).items[0].assign_activate = 0x0700; });
    ASSERT_TRUE(c.has("sii-dc"));
    EXPECT_NE(c.first("sii-dc")->message.find("AssignActivate"), std::string::npos);
    const Checked absent = check_edited([](Image& i) {
        std::erase_if(i.categories, [](const Category& x) { return x.type == category::dc; });
    });
    EXPECT_TRUE(absent.diagnostics.empty());
}

TEST(SiiCheck, TheDeviceOfAnImageIsFoundByIdentity) {
    std::string xml = esi::test::fixture_xml();
    const std::string device = xml.substr(xml.find("<Device "), xml.find("</Device>") + 9 - xml.find("<Device "));
    std::string second = device;
    second.replace(second.find("#x00020001"), 10, "#x00030001");
    xml.insert(xml.find("</Devices>"), second);
    const esi::test::Fixture f = esi::test::load_fixture(xml);
    Header h;
    h.product_code = 0x1234;
    h.revision_no = 0x00020001;
    ImageDevice m = find_device_for_image(f.document, h);
    ASSERT_NE(m.device, nullptr);
    EXPECT_TRUE(m.exact);
    EXPECT_EQ(m.device->type.revision_no, 0x00020001u);
    h.revision_no = 0x00090000;  // unknown revision: the newest with the product code
    m = find_device_for_image(f.document, h);
    ASSERT_NE(m.device, nullptr);
    EXPECT_FALSE(m.exact);
    EXPECT_EQ(m.device->type.revision_no, 0x00030001u);
    h.product_code = 0x9999;
    EXPECT_EQ(find_device_for_image(f.document, h).device, nullptr);  // two devices, neither fits
}

}  // namespace
