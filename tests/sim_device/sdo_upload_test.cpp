// SDO uploads from the model slave: every entry of every sample device's dictionary reads back
// as its default (checked against codegen's decoding of the same defaults), expedited, normal
// and segmented; complete access where the device declares it; the abort codes of reads.

#include <gtest/gtest.h>

#include <filesystem>

#include "esi/codegen/entry_values.hpp"
#include "esi/model/object_layout.hpp"
#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

// The bytes CoE transfers for an entry's default: what the codegen layer decodes, encoded in
// the entry's size (zeros where the model gives no default).
std::vector<std::uint8_t> expected_bytes(const ObjectEntry& entry) {
    const std::size_t size = (entry.bit_size + 7) / 8;
    std::vector<std::uint8_t> out(size, 0);
    const codegen::DecodedValue v = codegen::decode_entry_values(entry).default_value;
    using Kind = codegen::DecodedValue::Kind;
    switch (v.kind) {
        case Kind::signed_integer:
        case Kind::unsigned_integer:
        case Kind::real:
            for (std::size_t i = 0; i < size && i < 8; ++i) out[i] = static_cast<std::uint8_t>(v.bits >> (8 * i));
            if (v.kind == Kind::signed_integer && v.i < 0)
                for (std::size_t i = 8; i < size; ++i) out[i] = 0xFF;
            break;
        case Kind::string:
        case Kind::bytes: std::copy_n(v.text.begin(), std::min(v.text.size(), size), out.begin()); break;
        case Kind::none: break;
    }
    return out;
}

std::vector<std::string> sample_files() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(std::string(ESI_SOURCE_DIR) + "/samples"))
        if (e.path().extension() == ".yaml") out.push_back("samples/" + e.path().filename().string());
    std::sort(out.begin(), out.end());
    out.push_back("samples/esi/example-digital-io.xml");
    return out;
}

TEST(SdoUpload, EverySampleDictionaryReadsBackAsItsDefaults) {
    for (const std::string& file : sample_files()) {
        SCOPED_TRACE(file);
        Bench b(file);
        ASSERT_TRUE(b.ready());
        ASSERT_TRUE(b.master->to_preop());
        const Dictionary* dictionary = b.sample->device->dictionary();
        ASSERT_NE(dictionary, nullptr);
        std::size_t entries = 0;
        for (const Object& object : dictionary->objects) {
            const ObjectLayout layout = layout_of(dictionary, object);
            for (const ObjectEntry& entry : layout.entries) {
                SCOPED_TRACE(::testing::Message() << std::hex << object.index << ":" << entry.subindex);
                const SdoResult r = b.master->upload(static_cast<std::uint16_t>(object.index), static_cast<std::uint8_t>(entry.subindex));
                const std::string access = entry.flags && entry.flags->access ? *entry.flags->access : "ro";
                if (access == "wo") {
                    EXPECT_EQ(r.abort, 0x06010001u);
                    continue;
                }
                EXPECT_EQ(r.abort, 0u);
                EXPECT_EQ(r.data, expected_bytes(entry));
                ++entries;
            }
        }
        EXPECT_GT(entries, 10u);
    }
}

TEST(SdoUpload, MissingObjectAndSubIndexAreAborted) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    EXPECT_EQ(b.master->upload(0x5FFF, 0).abort, 0x06020000u);
    EXPECT_EQ(b.master->upload(0x1018, 9).abort, 0x06090011u);
    EXPECT_EQ(b.master->upload(0x1018, 1).abort, 0u);
}

TEST(SdoUpload, CompleteAccessIsRefusedWhereNotDeclared) {
    Bench b("samples/digital-io-8.yaml");  // complete_access: false
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    EXPECT_EQ(b.master->upload(0x1018, 0, true).abort, 0x06010004u);
}

TEST(SdoUpload, NoMailboxAnswerInInit) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    b.master->configure_mailbox();
    EXPECT_EQ(b.master->upload(0x1018, 1).abort, 0xFFFFFFFFu);  // nobody answers
}

}  // namespace
}  // namespace esi::sim::test_bench
