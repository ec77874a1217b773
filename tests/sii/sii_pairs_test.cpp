// The real EEPROM images of ../shared/corpus/sii against the images built from their ESI:
// every image decodes (faulty ones with the fault at the right offset), every pair checks, and
// the differences between the real and the built image are exactly the ones docs/sii.md
// explains.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "esi/sii/build.hpp"
#include "esi/sii/check.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/image_file.hpp"
#include "esi/sii/text.hpp"
#include "esi/xml/reader.hpp"
#include "image_diff.hpp"
#include "support/test_support.hpp"

namespace {

struct SiiManifestRow {
    std::string file;
    std::string pairs_with;  // "none" when the image has no ESI in the corpus
};

std::filesystem::path sii_dir() { return esi::test::shared_dir() / "corpus" / "sii"; }

std::vector<SiiManifestRow> sii_manifest() {
    std::vector<SiiManifestRow> rows;
    std::ifstream in(sii_dir() / "MANIFEST.tsv");
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<std::string> cols;
        std::stringstream s(line);
        std::string col;
        while (std::getline(s, col, '\t')) cols.push_back(col);
        if (cols.size() >= 6) rows.push_back({cols[0], cols[5]});
    }
    return rows;
}

std::vector<std::uint8_t> image_bytes(const std::string& file) {
    const auto loaded = esi::sii::load_image_file(sii_dir() / file);
    EXPECT_TRUE(loaded.bytes.has_value()) << file << ": " << loaded.error;
    return loaded.bytes.value_or(std::vector<std::uint8_t>{});
}

// Build the image the way the vendor's tool evidently did: PDO and DC categories only when the
// real image has them, names in the language the real image uses.
esi::sii::BuildOptions options_like(const esi::sii::Image& real, const esi::Device& device) {
    esi::sii::BuildOptions options;
    options.include_pdos = real.find(esi::sii::category::tx_pdo) || real.find(esi::sii::category::rx_pdo);
    options.include_dc = real.find(esi::sii::category::dc) != nullptr;
    if (const esi::sii::General* g = real.general())
        if (const auto name = real.string_at(g->name_idx))
            for (const auto& n : device.names)
                if (n.lcid && esi::sii::to_sii_text(n.text) == *name) options.name_lcid = *n.lcid;
    return options;
}

struct PairExpectation {
    // Fields of diff_images(built, real) that differ; each is explained in docs/sii.md.
    std::set<std::string> differences;
    // Rules of check_image(ESI, real image) at error or warning severity.
    std::set<std::string> check_rules;
};

// docs/sii.md, "The real images against the built ones", explains every entry.
const std::map<std::string, PairExpectation>& expectations() {
    static const std::set<std::string> soes_general = {"General.reserved_4", "General.flags", "General.byte14",
                                                       "General.physical_ports"};
    static const std::set<std::string> soes_rules = {"sii-general-flags", "sii-physical-ports"};
    auto with = [](std::set<std::string> base, std::initializer_list<std::string> more) {
        base.insert(more.begin(), more.end());
        return base;
    };
    static const std::map<std::string, PairExpectation> table = {
        {"SOES__linux_lan9252demo__soes.bin",
         {with(soes_general, {"General.coe_details"}), with(soes_rules, {"sii-general-coe"})}},
        {"SOES__raspberry_lan9252demo__soes.bin", {soes_general, soes_rules}},
        {"SOES__rtl_lwip_eoe_slave30__soes.bin",
         {{"General.flags", "General.byte14", "General.physical_ports"}, soes_rules}},
        {"SOES__rtl_xmc4_dynpdo__soes.bin", {soes_general, soes_rules}},
        {"SOES__tiesc_am335x__soes.bin", {soes_general, soes_rules}},
        {"SOES__xmc4300_slavedemo_esi__soes.bin",
         {{"Strings", "General.group", "General.order", "General.flags", "General.byte14", "DC.count", "DC 0.name", "DC 0.desc",
           "DC 0.sync0_factor"},
          {"sii-general-flags", "sii-general-strings", "sii-dc", "sii-string-index"}}},
        {"rt-labs__RTL_ATO_SPI_SLAVE__soes.bin",
         {{"Strings", "General.order", "General.reserved_4", "General.coe_details", "General.flags", "General.byte14",
           "General.physical_ports"},
          {"sii-general-coe", "sii-general-flags", "sii-physical-ports", "sii-general-strings"}}},
        {"Beckhoff__EK1100__ethercrab-dump.bin",
         {{"header word 0x20", "header word 0x21", "header word 0x22", "Strings", "General.reserved_4", "General.byte14"}, {}}},
        {"Beckhoff__EL2004__ethercrab-dump.bin", {{"Strings", "General.reserved_4", "General.byte14", "category 43"}, {}}},
        {"Beckhoff__EL2262__ethercrab-dump.bin",
         {{"header word 0x20", "header word 0x21", "header word 0x22", "Strings", "General.reserved_4", "General.sysman_class",
           "General.byte14", "RxPDO 0x1800 entry 0.data_type", "RxPDO 0x1880 entry 0.data_type", "DC 0.desc", "DC 1.desc",
           "DC 2.desc", "DC 3.desc", "category 42", "category 43"},
          {}}},
        {"Beckhoff__EL2828__ethercrab-dump.bin",
         {{"header word 0x21", "header word 0x22", "Strings", "General.reserved_4", "General.byte14", "category 3", "category 43"}, {}}},
    };
    return table;
}

TEST(SiiPairs, BuiltImagesDifferFromTheRealOnesOnlyWhereDocumented) {
    ESI_REQUIRE_CORPUS();
    std::size_t pairs = 0;
    const bool verbose = std::getenv("ESI_SII_VERBOSE") != nullptr;
    for (const auto& row : sii_manifest()) {
        if (row.pairs_with == "none") continue;
        SCOPED_TRACE(row.file);
        ++pairs;
        const auto bytes = image_bytes(row.file);
        const esi::sii::DecodedImage real = esi::sii::decode_image(bytes);
        const auto esi_path = esi::test::corpus_esi_dir() / row.pairs_with;
        const esi::ReadResult read = esi::read_esi_file(esi_path);
        ASSERT_TRUE(read.document.has_value());
        const esi::sii::ImageDevice match = esi::sii::find_device_for_image(*read.document, real.image.header);
        ASSERT_NE(match.device, nullptr);
        EXPECT_TRUE(match.exact) << "the image's identity is not in " << row.pairs_with;

        const auto options = options_like(real.image, *match.device);
        const esi::sii::BuildResult built = esi::sii::build_image(*match.info, *match.device, options, esi_path.string());
        ASSERT_TRUE(built.ok()) << built.diagnostics.items().front().message;
        EXPECT_EQ(built.bytes.size(), real.image.header.eeprom_bytes()) << "built image is not padded to the declared size";
        const esi::sii::DecodedImage mine = esi::sii::decode_image(built.bytes);

        std::set<std::string> differences;
        for (const auto& diff : esi::test::diff_images(mine.image, real.image)) {
            differences.insert(diff.field);
            if (verbose) std::printf("  %s: %s: built %s, real %s\n", row.file.c_str(), diff.field.c_str(), diff.built.c_str(), diff.real.c_str());
        }
        std::set<std::string> rules;
        for (const auto& d : esi::sii::check_image(*match.info, *match.device, real, esi_path.string(), row.file))
            if (d.severity != esi::Severity::info) rules.insert(d.rule);
        for (const auto& f : real.faults) rules.insert(f.rule);

        const auto it = expectations().find(row.file);
        ASSERT_NE(it, expectations().end()) << "a new pair: compare it and explain the differences in docs/sii.md";
        EXPECT_EQ(differences, it->second.differences);
        EXPECT_EQ(rules, it->second.check_rules);
    }
    EXPECT_EQ(pairs, expectations().size());
}

// The category types of an image in chain order, e.g. "10 30 40 41 51".
std::string category_list(const esi::sii::Image& image) {
    std::string out;
    for (const auto& c : image.categories) out += (out.empty() ? "" : " ") + std::to_string(c.type);
    return out;
}

// What the default build (no options: the image fits its EEPROM by leaving out optional content,
// docs/sii.md §1) may differ in from the real image, in identity, mailbox words, SyncM and the
// category list. Every entry is explained in docs/sii.md §5, "The default build".
const std::map<std::string, std::string>& default_build_category_differences() {
    static const std::map<std::string, std::string> table = {
        // The SOES tool writes no PDO categories, also where they fit.
        {"SOES__tiesc_am335x__soes.bin", "built 10 30 40 41 50 51, real 10 30 40 41"},
        // Written from another edit of the ESI: the real image has DC names in its strings but no
        // DC category.
        {"rt-labs__RTL_ATO_SPI_SLAVE__soes.bin", "built 10 30 40 41 60, real 10 30 40 41"},
        // FMMU_EX (42) and SyncUnit (43) have no public layout; libesi does not write them.
        {"Beckhoff__EL2004__ethercrab-dump.bin", "built 10 30 40 41 51, real 10 30 40 41 43 51"},
        {"Beckhoff__EL2262__ethercrab-dump.bin", "built 1 10 30 40 41 50 51 60, real 1 10 30 40 41 42 43 50 51 60"},
        {"Beckhoff__EL2828__ethercrab-dump.bin", "built 10 30 40 41 51, real 3 10 30 40 41 43 51"},
    };
    return table;
}

// The default build of every pair agrees with the real image in identity, standard and
// bootstrap mailbox words, mailbox protocols and SyncM category; the category lists differ only
// where default_build_category_differences() says so.
TEST(SiiPairs, DefaultBuildAgreesInIdentityMailboxSyncManagersAndCategories) {
    ESI_REQUIRE_CORPUS();
    std::size_t pairs = 0, same_categories = 0;
    for (const auto& row : sii_manifest()) {
        if (row.pairs_with == "none") continue;
        SCOPED_TRACE(row.file);
        ++pairs;
        const esi::sii::DecodedImage real = esi::sii::decode_image(image_bytes(row.file));
        const auto esi_path = esi::test::corpus_esi_dir() / row.pairs_with;
        const esi::ReadResult read = esi::read_esi_file(esi_path);
        ASSERT_TRUE(read.document.has_value());
        const esi::sii::ImageDevice match = esi::sii::find_device_for_image(*read.document, real.image.header);
        ASSERT_TRUE(match.exact);
        const esi::sii::BuildResult built = esi::sii::build_image(*match.info, *match.device, {}, esi_path.string());
        ASSERT_TRUE(built.ok()) << built.diagnostics.items().front().message;
        const esi::sii::Image& mine = esi::sii::decode_image(built.bytes).image;

        const esi::sii::Header& b = mine.header;
        const esi::sii::Header& r = real.image.header;
        EXPECT_EQ(b.vendor_id, r.vendor_id);
        EXPECT_EQ(b.product_code, r.product_code);
        EXPECT_EQ(b.revision_no, r.revision_no);
        EXPECT_EQ(b.serial_no, r.serial_no);
        EXPECT_EQ(b.size, r.size);
        EXPECT_EQ(b.bootstrap_receive_offset, r.bootstrap_receive_offset);
        EXPECT_EQ(b.bootstrap_receive_size, r.bootstrap_receive_size);
        EXPECT_EQ(b.bootstrap_send_offset, r.bootstrap_send_offset);
        EXPECT_EQ(b.bootstrap_send_size, r.bootstrap_send_size);
        EXPECT_EQ(b.standard_receive_offset, r.standard_receive_offset);
        EXPECT_EQ(b.standard_receive_size, r.standard_receive_size);
        EXPECT_EQ(b.standard_send_offset, r.standard_send_offset);
        EXPECT_EQ(b.standard_send_size, r.standard_send_size);
        EXPECT_EQ(b.mailbox_protocols, r.mailbox_protocols);
        for (const auto& diff : esi::test::diff_images(mine, real.image))
            EXPECT_NE(diff.field.rfind("SyncM", 0), 0u) << diff.field << ": built " << diff.built << ", real " << diff.real;

        const std::string built_list = category_list(mine), real_list = category_list(real.image);
        const auto explained = default_build_category_differences().find(row.file);
        if (built_list == real_list) {
            ++same_categories;
            EXPECT_EQ(explained, default_build_category_differences().end()) << "the category lists agree now; drop the entry";
        } else {
            ASSERT_NE(explained, default_build_category_differences().end())
                << "built " << built_list << ", real " << real_list << ": explain it in docs/sii.md";
            EXPECT_EQ("built " + built_list + ", real " + real_list, explained->second);
        }
    }
    std::printf("sii pairs: %zu of %zu default builds have the real image's category list\n", same_categories, pairs);
    EXPECT_EQ(pairs, expectations().size());
}

// Identity, mailbox, SyncManagers and PDOs of the Beckhoff terminals agree with the ESI to the bit.
TEST(SiiPairs, BeckhoffTerminalsMatchTheirEsiInIdentitySyncManagersAndPdos) {
    ESI_REQUIRE_CORPUS();
    for (const std::string file : {"Beckhoff__EK1100__ethercrab-dump.bin", "Beckhoff__EL2004__ethercrab-dump.bin",
                                   "Beckhoff__EL2262__ethercrab-dump.bin", "Beckhoff__EL2828__ethercrab-dump.bin"}) {
        SCOPED_TRACE(file);
        const std::string esi_file = file.find("EK1100") != std::string::npos ? "Beckhoff__EK11xx__dls-ethercat.xml" : "Beckhoff__EL2xxx__dls-ethercat.xml";
        const auto esi_path = esi::test::corpus_esi_dir() / esi_file;
        const esi::ReadResult read = esi::read_esi_file(esi_path);
        ASSERT_TRUE(read.document.has_value());
        const esi::sii::DecodedImage real = esi::sii::decode_image(image_bytes(file));
        EXPECT_TRUE(real.faults.empty());
        const auto match = esi::sii::find_device_for_image(*read.document, real.image.header);
        ASSERT_TRUE(match.exact);
        const auto mismatches = esi::sii::check_image(*match.info, *match.device, real, esi_path.string(), file);
        EXPECT_FALSE(mismatches.has_errors()) << (mismatches.empty() ? "" : mismatches.items().front().message);
        EXPECT_EQ(mismatches.count(esi::Severity::warning), 0u);
    }
}

struct DumpExpectation {
    std::set<std::string> rules;  // fault rules of decode_image
    std::uint64_t first_error_offset = 0;
};

TEST(SiiPairs, EveryCorpusImageDecodesAndFaultyOnesAreLocated) {
    ESI_REQUIRE_CORPUS();
    const std::map<std::string, DumpExpectation> faulty = {
        // An empty EEPROM read from a device: zeroed header (bad CRC, version 0, size word 0)
        // and blank memory where the categories would be.
        {"Empty__issue-286__ethercrab-dump.bin",
         {{"sii-crc", "sii-version", "sii-chain-past-size", "sii-chain-blank", "sii-larger-than-size"}, 0x0E}},
        // The strings of this AKD dump were blanked without fixing the category length, so the
        // chain lands in the middle of the data: category 0x0100 with 1280 words at 0x028A.
        {"Kollmorgen__AKD_null_strings__ethercrab-dump.bin", {{"sii-category-overrun"}, 0x028A}},
        // A truncated image whose DC op modes name strings that are not in it (warning only).
        {"SOES__xmc4300_slavedemo_esi__soes.bin", {{"sii-string-index"}, 0}},
    };
    std::size_t images = 0;
    for (const auto& row : sii_manifest()) {
        SCOPED_TRACE(row.file);
        ++images;
        const esi::sii::DecodedImage decoded = esi::sii::decode_image(image_bytes(row.file));
        std::set<std::string> rules;
        for (const auto& f : decoded.faults) rules.insert(f.rule);
        const auto it = faulty.find(row.file);
        if (it == faulty.end()) {
            EXPECT_TRUE(rules.empty()) << *rules.begin();
            EXPECT_TRUE(decoded.end_offset.has_value());
            EXPECT_NE(decoded.image.general(), nullptr);
            continue;
        }
        EXPECT_EQ(rules, it->second.rules);
        if (it->second.first_error_offset != 0) {
            ASSERT_TRUE(decoded.has_errors());
            const auto first = std::find_if(decoded.faults.begin(), decoded.faults.end(),
                                            [](const auto& f) { return f.severity == esi::Severity::error; });
            EXPECT_EQ(first->offset, it->second.first_error_offset);
        } else {
            EXPECT_FALSE(decoded.has_errors());
        }
    }
    EXPECT_EQ(images, 14u);
}

}  // namespace
