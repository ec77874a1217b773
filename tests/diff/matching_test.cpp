// How devices pair up between the files: by (vendor, ProductCode, RevisionNo); a new revision is
// compared with its predecessor (the highest lower revision of the product in the old file);
// devices without a ProductCode by their Type text; --device narrows the comparison. And what
// the revision context does to the classes and to the revision-not-changed error.

#include <gtest/gtest.h>

#include "diff_fixture.hpp"

namespace {

using esi::ChangeClass;
using esi::ChangeKind;
using esi::test::diff_base;
using esi::test::diff_texts;
using esi::test::edit;

std::string catalogue(const std::string& devices) {
    return R"(<?xml version="1.0"?>
<EtherCATInfo>
  <Vendor><Id>7</Id><Name>V</Name></Vendor>
  <Descriptions>
    <Groups><Group><Type>G</Type><Name>G</Name></Group></Groups>
    <Devices>
)" + devices +
           R"(
    </Devices>
  </Descriptions>
</EtherCATInfo>
)";
}

// A device whose one TxPdo entry has `bits` bits.
std::string device(const std::string& code, const std::string& revision, int bits, const std::string& name = "D") {
    std::string type = "<Type";
    if (!code.empty()) type += " ProductCode=\"" + code + "\"";
    if (!revision.empty()) type += " RevisionNo=\"" + revision + "\"";
    type += ">" + name + "</Type>";
    return "<Device Physics=\"YY\">" + type + "<Name>" + name + "</Name><GroupType>G</GroupType>" +
           "<Sm StartAddress=\"#x1000\" ControlByte=\"#x20\" Enable=\"1\">Inputs</Sm>" +
           "<TxPdo Fixed=\"1\" "
           "Sm=\"0\"><Index>#x1A00</Index><Name>In</Name><Entry><Index>#x6000</Index><SubIndex>1</SubIndex><BitLen>" +
           std::to_string(bits) + "</BitLen><Name>x</Name></Entry></TxPdo></Device>\n";
}

std::size_t count(const esi::DiffResult& r, ChangeKind kind) {
    std::size_t n = 0;
    for (const auto& c : r.changes) n += c.kind == kind;
    return n;
}

TEST(DiffMatching, NewRevisionReplacingTheOldIsComparedWithItWithoutTheRevisionError) {
    const auto r = diff_texts(catalogue(device("#x10", "1", 8)), catalogue(device("#x10", "2", 16)));
    SCOPED_TRACE(esi::test::describe(r));
    const esi::Change* revision = esi::test::find_change(r, ChangeKind::revision_changed);
    ASSERT_NE(revision, nullptr);
    EXPECT_EQ(revision->old_value, "#x00000001");
    EXPECT_EQ(revision->new_value, "#x00000002");
    ASSERT_TRUE(revision->device);
    EXPECT_EQ(revision->device->revision, 2u);
    EXPECT_EQ(revision->device->compared_revision, 1u);
    const esi::Change* bits = esi::test::find_change(r, ChangeKind::pdo_entry_bit_len_changed);
    ASSERT_NE(bits, nullptr);
    EXPECT_EQ(bits->change_class, ChangeClass::breaking);  // the old revision is gone: the changes count fully
    EXPECT_EQ(esi::test::find_change(r, ChangeKind::revision_not_changed), nullptr);
    EXPECT_EQ(r.verdict, esi::Verdict::breaking);
}

TEST(DiffMatching, NewRevisionNextToTheOldOneIsAtMostCompatible) {
    const auto r = diff_texts(catalogue(device("#x10", "1", 8)), catalogue(device("#x10", "1", 8) + device("#x10", "2", 16)));
    SCOPED_TRACE(esi::test::describe(r));
    ASSERT_NE(esi::test::find_change(r, ChangeKind::device_revision_added), nullptr);
    const esi::Change* bits = esi::test::find_change(r, ChangeKind::pdo_entry_bit_len_changed);
    ASSERT_NE(bits, nullptr);
    EXPECT_EQ(bits->change_class, ChangeClass::compatible);
    EXPECT_NE(bits->message.find("still described"), std::string::npos) << bits->message;
    EXPECT_EQ(r.verdict, esi::Verdict::compatible);
}

TEST(DiffMatching, PredecessorIsTheHighestLowerRevision) {
    const auto r = diff_texts(catalogue(device("#x10", "1", 8) + device("#x10", "2", 16) + device("#x10", "4", 32)),
                              catalogue(device("#x10", "3", 16)));
    SCOPED_TRACE(esi::test::describe(r));
    const esi::Change* revision = esi::test::find_change(r, ChangeKind::revision_changed);
    ASSERT_NE(revision, nullptr);
    EXPECT_EQ(revision->device->compared_revision, 2u);
    EXPECT_EQ(esi::test::find_change(r, ChangeKind::pdo_entry_bit_len_changed), nullptr);  // 2 and 3 have the same layout
    EXPECT_EQ(count(r, ChangeKind::device_removed), 2u);                                   // revisions 1 and 4
}

TEST(DiffMatching, LowerRevisionWithoutPredecessorIsAnAddedDevice) {
    const auto r = diff_texts(catalogue(device("#x10", "5", 8)), catalogue(device("#x10", "5", 8) + device("#x10", "3", 8)));
    EXPECT_EQ(count(r, ChangeKind::device_added), 1u) << esi::test::describe(r);
    EXPECT_EQ(r.verdict, esi::Verdict::compatible);
}

TEST(DiffMatching, DevicesWithoutProductCodeMatchByTypeText) {
    const auto r = diff_texts(catalogue(device("", "", 8, "Alpha") + device("", "", 8, "Beta")),
                              catalogue(device("", "", 8, "Beta") + device("", "", 16, "Alpha")));
    SCOPED_TRACE(esi::test::describe(r));
    ASSERT_EQ(r.changes.size(), 2u);  // the BitLen change of Alpha and its revision error
    EXPECT_EQ(r.changes[0].kind, ChangeKind::revision_not_changed);
    EXPECT_EQ(r.changes[1].kind, ChangeKind::pdo_entry_bit_len_changed);
    EXPECT_EQ(r.changes[1].device->name, "Alpha");
}

TEST(DiffMatching, ProductCodeChangeIsARemovalAndAnAddition) {
    const auto r = diff_texts(catalogue(device("#x10", "1", 8)), catalogue(device("#x11", "1", 8)));
    EXPECT_EQ(count(r, ChangeKind::device_removed), 1u);
    EXPECT_EQ(count(r, ChangeKind::device_added), 1u);
    EXPECT_EQ(r.verdict, esi::Verdict::breaking);
    EXPECT_EQ(esi::test::find_change(r, ChangeKind::revision_not_changed), nullptr);
}

TEST(DiffMatching, DuplicateIdentitiesPairInOrder) {
    const auto r = diff_texts(catalogue(device("#x10", "1", 8) + device("#x10", "1", 16)),
                              catalogue(device("#x10", "1", 8) + device("#x10", "1", 32)));
    EXPECT_EQ(count(r, ChangeKind::pdo_entry_bit_len_changed), 1u) << esi::test::describe(r);
}

TEST(DiffMatching, DeviceSelectorLimitsTheComparison) {
    std::string x = edit(diff_base, "<BitLen>4</BitLen>", "<BitLen>8</BitLen>");                         // device #x1001
    x = edit(x, "<BitLen>1</BitLen>", "<BitLen>2</BitLen>");                                             // device #x2002
    x = edit(x, "<Name LcId=\"1033\">Example Automation</Name>", "<Name LcId=\"1033\">Renamed</Name>");  // the file
    std::string error;
    esi::DiffOptions options;
    options.device = esi::parse_device_selector("#x2002", error);
    ASSERT_TRUE(options.device) << error;
    const auto r = diff_texts(diff_base, x, options);
    SCOPED_TRACE(esi::test::describe(r));
    EXPECT_EQ(r.old_devices_compared, 1u);
    EXPECT_EQ(r.new_devices_compared, 1u);
    for (const auto& c : r.changes) {
        ASSERT_TRUE(c.device);
        EXPECT_EQ(c.device->product_code, 0x2002u);
    }
    EXPECT_NE(esi::test::find_change(r, ChangeKind::pdo_entry_bit_len_changed), nullptr);

    options.device = esi::parse_device_selector("0x2002:1", error);  // no device has revision 1
    const auto none = diff_texts(diff_base, x, options);
    EXPECT_EQ(none.old_devices_compared + none.new_devices_compared, 0u);
    EXPECT_TRUE(none.identical());
}

TEST(DiffMatching, SelectedNewRevisionStillFindsItsPredecessor) {
    esi::DiffOptions options;
    std::string error;
    options.device = esi::parse_device_selector("16:2", error);
    const auto r = diff_texts(catalogue(device("#x10", "1", 8)), catalogue(device("#x10", "2", 16)), options);
    EXPECT_NE(esi::test::find_change(r, ChangeKind::revision_changed), nullptr) << esi::test::describe(r);
    EXPECT_NE(esi::test::find_change(r, ChangeKind::pdo_entry_bit_len_changed), nullptr);
}

TEST(DiffMatching, BreakingModuleChangeRaisesTheErrorOnDevicesWhoseSlotsAcceptIt) {
    const std::string x = edit(diff_base, "<Entry><Index>#x6040</Index><SubIndex>1</SubIndex><BitLen>16</BitLen>",
                               "<Entry><Index>#x6040</Index><SubIndex>1</SubIndex><BitLen>32</BitLen>");
    const auto r = diff_texts(diff_base, x);
    SCOPED_TRACE(esi::test::describe(r));
    const esi::Change* error = esi::test::find_change(r, ChangeKind::revision_not_changed);
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->device->product_code, 0x1001u);  // the device with the slot, not the other one
    EXPECT_NE(error->message.find("modules"), std::string::npos);
    EXPECT_EQ(count(r, ChangeKind::revision_not_changed), 1u);
}

TEST(DiffMatching, UnreadableOrEmptyModelsDoNotCrash) {
    const esi::EsiDocument empty;
    const esi::EsiDocument base = esi::test::read_document(diff_base);
    const auto added = esi::diff_documents(empty, base);
    EXPECT_EQ(count(added, ChangeKind::device_added), 2u);
    const auto removed = esi::diff_documents(base, empty);
    EXPECT_EQ(count(removed, ChangeKind::device_removed), 2u);
    EXPECT_EQ(removed.verdict, esi::Verdict::breaking);
    EXPECT_TRUE(esi::diff_documents(empty, empty).identical());
}

TEST(DiffMatching, ResultIsSortedByDeviceThenClassThenPath) {
    std::string x = edit(diff_base, "<BitLen>4</BitLen>", "<BitLen>8</BitLen>");
    x = edit(x, "Beispielgerät", "Beispiel");
    x = edit(x, "<Name LcId=\"1033\">Example Automation</Name>", "<Name LcId=\"1033\">Renamed</Name>");
    x = edit(x, "<BitLen>1</BitLen>", "<BitLen>2</BitLen>");
    const auto r = diff_texts(diff_base, x);
    SCOPED_TRACE(esi::test::describe(r));
    ASSERT_GE(r.changes.size(), 5u);
    EXPECT_FALSE(r.changes[0].device.has_value());  // the file first
    EXPECT_EQ(r.changes[1].device->product_code, 0x1001u);
    EXPECT_EQ(r.changes[1].kind, ChangeKind::revision_not_changed);  // the error leads its device
    EXPECT_EQ(r.changes[2].change_class, ChangeClass::breaking);
    EXPECT_EQ(r.changes[3].change_class, ChangeClass::cosmetic);
    EXPECT_EQ(r.changes.back().device->product_code, 0x2002u);
}

}  // namespace
