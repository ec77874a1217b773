// Round trip over the real vendor files (skipped without ../shared): every device of every
// well-formed EtherCATInfo file is built, the bytes decoded again, and the decoded header words
// and categories compared with the ESI's own fields; an image built from an ESI must also check
// clean against it. An image larger than its EEPROM leaves out optional content in the documented
// order (docs/sii.md §1): what it leaves out must be exactly what is missing from the image.

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <set>

#include "esi/sii/build.hpp"
#include "esi/sii/check.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"
#include "esi/sii/mapping.hpp"
#include "esi/sii/text.hpp"
#include "esi/xml/reader.hpp"
#include "support/test_support.hpp"

namespace {

using esi::sii::DecodedImage;

// What the round trip compares, written against the model directly (not through mapping.hpp),
// so that a wrong mapping shows up here and not only in both builder and checker.
void expect_fields(const esi::EtherCATInfo& info, const esi::Device& device, const DecodedImage& decoded,
                   const esi::sii::BuildOptions& options, const esi::sii::Omissions& omitted, const std::string& where) {
    SCOPED_TRACE(where);
    const esi::sii::Image& image = decoded.image;
    const esi::sii::Header& h = image.header;
    if (info.vendor && info.vendor->id) { EXPECT_EQ(h.vendor_id, *info.vendor->id); }
    EXPECT_EQ(h.product_code, device.type.product_code.value_or(0));
    EXPECT_EQ(h.revision_no, device.type.revision_no.value_or(0));
    EXPECT_EQ(h.version, 1);
    EXPECT_EQ(h.mailbox_protocols, device.mailbox ? device.mailbox->protocol_bits() : 0);
    if (device.eeprom && device.eeprom->config_data) {
        const auto bytes = device.eeprom->config_data->bytes();
        ASSERT_TRUE(bytes.has_value());
        for (std::size_t i = 0; i < bytes->size() && i < 14; ++i) { EXPECT_EQ(h.config_data[i], (*bytes)[i]) << "config byte " << i; }
    }
    if (device.eeprom && device.eeprom->byte_size) { EXPECT_EQ(h.size, *device.eeprom->byte_size / 128 - 1); }
    if (device.eeprom && device.eeprom->boot_strap) {
        const auto b = device.eeprom->boot_strap->bytes();
        ASSERT_TRUE(b && b->size() == 8);
        EXPECT_EQ(h.bootstrap_receive_offset, (*b)[0] | ((*b)[1] << 8));
        EXPECT_EQ(h.bootstrap_send_size, (*b)[6] | ((*b)[7] << 8));
    }
    for (const auto& sm : device.sms) {
        if (sm.type == "MBoxOut") {
            EXPECT_EQ(h.standard_receive_offset, sm.start_address.value_or(0));
            EXPECT_EQ(h.standard_receive_size, sm.default_size.value_or(0));
            break;
        }
    }

    const esi::sii::General* g = image.general();
    ASSERT_NE(g, nullptr);
    // The General category's strings, unless left out to fit (docs/sii.md §1, steps 6-8).
    if (omitted.order_string) { EXPECT_EQ(g->order_idx, 0); }
    else { EXPECT_EQ(image.string_at(g->order_idx).value_or(""), esi::sii::to_sii_text(device.type.text)); }
    if (omitted.group_string) { EXPECT_EQ(g->group_idx, 0); }
    else if (device.group_type && !device.group_type->empty()) {
        EXPECT_EQ(image.string_at(g->group_idx).value_or(""), esi::sii::to_sii_text(*device.group_type));
    }
    const auto name = image.string_at(g->name_idx);
    if (omitted.name_string) { EXPECT_EQ(g->name_idx, 0); }
    else { ASSERT_TRUE(name.has_value() || device.names.empty()); }
    if (name) { EXPECT_EQ(*name, esi::sii::to_sii_text(esi::primary_text(device.names))); }
    const bool coe = device.mailbox && device.mailbox->coe;
    EXPECT_EQ((g->coe_details & 0x01) != 0, coe);
    if (coe) {
        EXPECT_EQ((g->coe_details & 0x02) != 0, device.mailbox->coe->sdo_info.value_or(false));
        EXPECT_EQ((g->coe_details & 0x20) != 0, device.mailbox->coe->complete_access.value_or(false));
    }
    EXPECT_EQ(g->foe_details != 0, device.mailbox && device.mailbox->foe.has_value());
    for (std::size_t port = 0; port < device.physics.size() && port < 4; ++port) {
        const char c = device.physics[port];
        const unsigned expected = (c == 'Y' || c == 'H') ? 1u : c == 'K' ? 3u : 0u;
        EXPECT_EQ(g->port(static_cast<unsigned>(port)), expected) << "port " << port;
    }

    if (!device.fmmus.empty()) {
        ASSERT_NE(image.fmmus(), nullptr);
        const auto& usages = image.fmmus()->usages;
        ASSERT_GE(usages.size(), device.fmmus.size());
        for (std::size_t i = 0; i < device.fmmus.size(); ++i) {
            const std::string& t = device.fmmus[i].type;
            const unsigned expected = t == "Outputs" ? 1u : t == "Inputs" ? 2u : t == "MBoxState" ? 3u : usages[i];
            EXPECT_EQ(usages[i], expected) << "FMMU " << i;
        }
    }
    if (!device.sms.empty()) {
        ASSERT_NE(image.sync_managers(), nullptr);
        const auto& sms = image.sync_managers()->items;
        ASSERT_EQ(sms.size(), device.sms.size());
        for (std::size_t i = 0; i < sms.size(); ++i) {
            EXPECT_EQ(sms[i].start_address, device.sms[i].start_address.value_or(0)) << "SM " << i;
            EXPECT_EQ(sms[i].control, device.sms[i].control_byte.value_or(0)) << "SM " << i;
            EXPECT_EQ(sms[i].length, device.sms[i].default_size.value_or(0)) << "SM " << i;
            const std::string& t = device.sms[i].type;
            if (t == "MBoxOut") { EXPECT_EQ(sms[i].type, 1); }
            if (t == "MBoxIn") { EXPECT_EQ(sms[i].type, 2); }
            if (t == "Outputs") { EXPECT_EQ(sms[i].type, 3); }
            if (t == "Inputs") { EXPECT_EQ(sms[i].type, 4); }
        }
    }

    for (const auto& [type, pdos] : {std::pair{esi::sii::category::tx_pdo, &device.tx_pdos}, std::pair{esi::sii::category::rx_pdo, &device.rx_pdos}}) {
        std::vector<const esi::Pdo*> kept;
        for (const auto& pdo : *pdos)
            if (!omitted.unassigned_pdos || pdo.sm) kept.push_back(&pdo);
        if (kept.empty() || !options.include_pdos || omitted.pdos) {
            EXPECT_EQ(image.find(type), nullptr);
            continue;
        }
        const esi::sii::Pdos* decoded_pdos = image.pdos(type);
        ASSERT_NE(decoded_pdos, nullptr);
        ASSERT_EQ(decoded_pdos->items.size(), kept.size());
        for (std::size_t i = 0; i < kept.size(); ++i) {
            const esi::Pdo& pdo = *kept[i];
            const esi::sii::PdoRecord& r = decoded_pdos->items[i];
            EXPECT_EQ(r.index, pdo.index);
            EXPECT_EQ(r.sync_manager, pdo.sm ? *pdo.sm : 0xFFu);
            EXPECT_EQ((r.flags & 0x0001) != 0, pdo.mandatory.value_or(false));
            EXPECT_EQ((r.flags & 0x0010) != 0, pdo.fixed.value_or(false));
            if (!pdo.names.empty()) { EXPECT_EQ(image.string_at(r.name_idx).value_or(""), esi::sii::to_sii_text(esi::primary_text(pdo.names))); }
            ASSERT_EQ(r.entries.size(), pdo.entries.size());
            for (std::size_t k = 0; k < r.entries.size(); ++k) {
                EXPECT_EQ(r.entries[k].index, pdo.entries[k].index);
                EXPECT_EQ(r.entries[k].subindex, pdo.entries[k].effective_subindex());
                EXPECT_EQ(r.entries[k].bit_len, pdo.entries[k].bit_len);
            }
        }
    }

    std::vector<const esi::DcOpMode*> written;
    if (device.dc && options.include_dc && !omitted.dc)
        for (const auto& op : device.dc->op_modes)
            if (!esi::sii::is_legacy_op_mode(op)) written.push_back(&op);
    if (written.empty()) {
        EXPECT_EQ(image.find(esi::sii::category::dc), nullptr);
    } else {
        ASSERT_NE(image.dc(), nullptr);
        ASSERT_EQ(image.dc()->items.size(), written.size());
        for (std::size_t i = 0; i < written.size(); ++i) {
            const auto& r = image.dc()->items[i];
            EXPECT_EQ(r.assign_activate, written[i]->assign_activate);
            EXPECT_EQ(image.string_at(r.name_idx).value_or(""), esi::sii::to_sii_text(written[i]->name));
            const bool described = written[i]->desc && !written[i]->desc->empty() && !omitted.dc_descriptions;
            EXPECT_EQ(r.desc_idx != 0, described);
            if (written[i]->cycle_time_sync0) {
                EXPECT_EQ(r.cycle_time0, static_cast<std::uint32_t>(written[i]->cycle_time_sync0->value));
                EXPECT_EQ(r.sync0_cycle_factor, written[i]->cycle_time_sync0->factor.value_or(0));
            }
        }
    }
}

bool has_explicit_standard_category(const esi::Device& device) {
    if (!device.eeprom) return false;
    for (const auto& cat : device.eeprom->categories)
        for (const unsigned type : {10u, 30u, 40u, 41u, 50u, 51u, 60u})
            if (cat.cat_no == type) return true;
    return false;
}

bool is_capacity_rule(const std::string& rule) {
    return rule == "sii-image-too-large" || rule == "sii-too-many-strings" || rule == "sii-string-too-long";
}

TEST(SiiCorpus, EveryDeviceOfEveryWellFormedFileRoundTrips) {
    ESI_REQUIRE_CORPUS();
    std::size_t files = 0, devices = 0, clean = 0, from_data = 0, too_large = 0, explicit_categories = 0, needs_no_pdo_dc = 0;
    std::size_t pdi_off_images = 0;
    std::map<std::string, std::size_t> fitted;  // the last step a fitted image needed -> devices
    std::set<std::string> rules_seen;
    for (const auto& [file, notes] : esi::test::corpus_manifest()) {
        if (notes.find("root=EtherCATInfo") == std::string::npos) continue;
        if (notes.find("NOT WELL-FORMED") != std::string::npos) continue;
        const auto path = esi::test::corpus_esi_dir() / file;
        const esi::ReadResult read = esi::read_esi_file(path, {.keep_source = false});
        ASSERT_TRUE(read.document.has_value()) << file;
        ++files;
        for (const auto& info : read.document->infos) {
            for (const auto& device : info.devices) {
                ++devices;
                const std::string where = file + " " + device.type.text;
                const esi::sii::BuildResult built = esi::sii::build_image(info, device, {}, path.string());
                for (const auto& d : built.diagnostics) {
                    if (d.severity != esi::Severity::error) continue;
                    rules_seen.insert(d.rule);
                    EXPECT_TRUE(is_capacity_rule(d.rule)) << where << ": " << d.message << " [" << d.rule << "]";
                }
                const DecodedImage decoded = esi::sii::decode_image(built.bytes);
                if (built.from_eeprom_data) {
                    ++from_data;
                    EXPECT_EQ(built.bytes, *device.eeprom->data->bytes()) << where;
                    continue;
                }
                if (has_explicit_standard_category(device)) {
                    // The vendor's own General/SyncM/... bytes win over the generated ones; they
                    // must be in the image exactly, whatever they say.
                    ++explicit_categories;
                    for (const auto& cat : device.eeprom->categories) {
                        const esi::sii::Category* c = decoded.image.find(static_cast<std::uint16_t>(cat.cat_no));
                        ASSERT_NE(c, nullptr) << where << " CatNo " << cat.cat_no;
                        std::vector<std::uint8_t> expected = cat.data ? *cat.data->bytes() : std::vector<std::uint8_t>{};
                        if (expected.size() % 2) expected.push_back(0);
                        const auto payload = built.bytes.begin() + static_cast<std::ptrdiff_t>(c->offset + 4u);
                        EXPECT_EQ(std::vector<std::uint8_t>(payload, payload + 2 * c->declared_words), expected)
                            << where << " CatNo " << cat.cat_no;
                    }
                    continue;
                }
                if (built.ok()) {
                    ++clean;
                    // A device without ConfigData gets an image whose PDI is off; the builder warned
                    // (sii-pdi-off) and the decoder reports it when the device has a mailbox or
                    // process data. No other fault.
                    const bool pdi_off = !device.eeprom || !device.eeprom->config_data;
                    for (const auto& f : decoded.faults)
                        if (f.severity == esi::Severity::error) {
                            EXPECT_TRUE(pdi_off && f.rule == "sii-pdi-off") << where << ": " << f.message;
                            if (f.rule == "sii-pdi-off") ++pdi_off_images;
                        }
                    EXPECT_EQ(decoded.byte_count, built.eeprom_bytes) << where;
                    const esi::Diagnostics mismatches = esi::sii::check_image(info, device, decoded, path.string(), "built.bin");
                    EXPECT_FALSE(mismatches.has_errors()) << where << ": " << mismatches.items().front().message;
                    // Left-out General strings are the one warning check gives (sii-general-strings).
                    const bool strings_left_out = built.omitted.group_string || built.omitted.order_string || built.omitted.name_string;
                    for (const auto& m : mismatches)
                        if (m.severity == esi::Severity::warning) {
                            EXPECT_TRUE(strings_left_out && m.rule == "sii-general-strings") << where << ": " << m.message;
                        }
                    expect_fields(info, device, decoded, {}, built.omitted, where);
                    EXPECT_EQ(built.omitted.any(), !built.left_out.empty()) << where;
                    if (!built.left_out.empty()) {
                        // "the order number \"BK1120\" (General, Type)" -> "the order number"
                        std::string last = built.left_out.back().substr(0, built.left_out.back().find_first_of("(\""));
                        while (!last.empty() && last.back() == ' ') last.pop_back();
                        ++fitted[last];
                        // Without the fit the same device is refused.
                        esi::sii::BuildOptions strict;
                        strict.fit_to_eeprom = false;
                        EXPECT_FALSE(esi::sii::build_image(info, device, strict, path.string()).ok()) << where;
                    }
                    continue;
                }
                // Over capacity: the diagnostics said so (checked above). The same device must
                // round-trip once the limit is lifted: without ByteSize (the builder then sizes the
                // EEPROM), and if the strings still overflow, without PDO and DC categories.
                ++too_large;
                if (std::getenv("ESI_SII_VERBOSE")) {
                    for (const auto& d : built.diagnostics)
                        if (d.severity == esi::Severity::error) std::printf("  over capacity: %s: %s\n", where.c_str(), d.message.c_str());
                }
                esi::Device unlimited = device;
                if (unlimited.eeprom) unlimited.eeprom->byte_size.reset();
                esi::sii::BuildOptions options;
                esi::sii::BuildResult rebuilt = esi::sii::build_image(info, unlimited, options, path.string());
                if (!rebuilt.ok()) {
                    ++needs_no_pdo_dc;
                    options.include_pdos = false;
                    options.include_dc = false;
                    rebuilt = esi::sii::build_image(info, unlimited, options, path.string());
                }
                ASSERT_TRUE(rebuilt.ok()) << where << ": " << rebuilt.diagnostics.items().front().message;
                const DecodedImage again = esi::sii::decode_image(rebuilt.bytes);
                EXPECT_FALSE(again.has_errors()) << where;
                expect_fields(info, unlimited, again, options, rebuilt.omitted, where);
            }
        }
    }
    std::size_t fitted_total = 0;
    for (const auto& [step, count] : fitted) fitted_total += count;
    std::printf("sii corpus: %zu files, %zu devices: %zu built and checked clean (%zu of them fit by leaving out optional "
                "content); %zu whose mandatory part does not fit (%zu of them fit only without PDO/DC once unlimited); %zu "
                "with the vendor's own standard categories; %zu Eeprom/Data as is\n",
                files, devices, clean, fitted_total, too_large, needs_no_pdo_dc, explicit_categories, from_data);
    for (const auto& [step, count] : fitted) std::printf("sii corpus:   %zu fit with, last, %s left out\n", count, step.c_str());
    std::printf("sii corpus: %zu built images switch the PDI off (no ConfigData, but process data or a mailbox)\n", pdi_off_images);
    EXPECT_GT(clean, 800u);
}

}  // namespace
