// esi-diff on the real revision pairs of the corpus (MANIFEST.tsv "revision pair" notes). Every
// expectation below was checked by reading both files (grep/xmllint of the elements named); the
// comments say what the files contain. Skipped when ../shared is absent.

#include <gtest/gtest.h>

#include "esi/diff/classification.hpp"
#include "esi/diff/diff.hpp"
#include "esi/diff/report.hpp"
#include "support/test_support.hpp"

namespace {

using esi::ChangeClass;
using esi::ChangeKind;
using esi::Verdict;

esi::DiffResult pair(const std::string& old_name, const std::string& new_name) {
    const auto dir = esi::test::corpus_esi_dir();
    EXPECT_TRUE(std::filesystem::exists(dir / old_name)) << old_name;
    EXPECT_TRUE(std::filesystem::exists(dir / new_name)) << new_name;
    const esi::FileDiff diff = esi::diff_files(dir / old_name, dir / new_name);
    EXPECT_TRUE(diff.result.has_value()) << (diff.diagnostics.empty() ? "" : diff.diagnostics.items()[0].message);
    return diff.result ? *diff.result : esi::DiffResult{};
}

std::string listing(const esi::DiffResult& r) { return esi::render_diff_text(r, {"old", "new"}); }

const esi::Change* at(const esi::DiffResult& r, ChangeKind kind, const std::string& path) {
    for (const auto& c : r.changes)
        if (c.kind == kind && c.path == path) return &c;
    return nullptr;
}

std::size_t count(const esi::DiffResult& r, ChangeKind kind) {
    std::size_t n = 0;
    for (const auto& c : r.changes) n += c.kind == kind;
    return n;
}

TEST(CorpusPairs, EaserCat7000ChangesProcessDataUnderTheSameRevision) {
    ESI_REQUIRE_CORPUS();
    // Both files: ProductCode #x7000 RevisionNo #x2. 2025-10 splits the single REAL entries of
    // RxPdo 0x1601/0x1602 and TxPdo 0x1A01/0x1A02 into records (#x7001:01..06 …) and drops TxPdo
    // 0x1A03 'Status' with its objects 0x1A03 and 0x6003 (24 -> 22 objects).
    const auto r = pair("MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-02.xml",
                        "MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-10.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::breaking);
    EXPECT_EQ(r.error_count(), 1u);
    ASSERT_NE(at(r, ChangeKind::revision_not_changed, "Type@RevisionNo"), nullptr);
    EXPECT_NE(at(r, ChangeKind::pdo_removed, "TxPdo[#x1A03]"), nullptr);
    const esi::Change* first = at(r, ChangeKind::pdo_entry_index_changed, "RxPdo[#x1601]/Entry[#x7001:00]/Index");
    ASSERT_NE(first, nullptr);
    EXPECT_NE(first->new_value->find("#x7001:01"), std::string::npos);
    for (const char* sub : {"02", "03", "04", "05", "06"})
        EXPECT_NE(at(r, ChangeKind::pdo_entry_added, std::string("RxPdo[#x1601]/Entry[#x7001:") + sub + "]"), nullptr) << sub;
    const esi::Change* type = at(r, ChangeKind::pdo_entry_data_type_changed, "TxPdo[#x1A02]/Entry[#x6002:01]/DataType");
    ASSERT_NE(type, nullptr);
    EXPECT_EQ(type->old_value, "REAL");
    EXPECT_EQ(type->new_value, "DINT");
    EXPECT_NE(at(r, ChangeKind::object_removed, "Dictionary/Object[#x1A03]"), nullptr);
    EXPECT_NE(at(r, ChangeKind::object_removed, "Dictionary/Object[#x6003]"), nullptr);
    EXPECT_NE(at(r, ChangeKind::object_entry_removed, "Dictionary/Object[#x1C13:04]"), nullptr);
    EXPECT_EQ(count(r, ChangeKind::device_added) + count(r, ChangeKind::device_removed), 0u);
}

TEST(CorpusPairs, SmcEx250OnlyDeclaresTheSyncManagerTypes) {
    ESI_REQUIRE_CORPUS();
    // 2014-03 writes "Outputs" into the two empty Sm elements; it also dropped the UTF-8 BOM and
    // added a final newline, which are not changes.
    const auto r = pair("SMC__EX250-SEN1-X156__dls-ethercat__2011-05.xml", "SMC__EX250-SEN1-X156__dls-ethercat__2014-03.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::compatible);
    ASSERT_EQ(r.changes.size(), 2u);
    for (const char* sm : {"Sm[0]", "Sm[1]"}) {
        const esi::Change* c = at(r, ChangeKind::sm_type_declared, sm);
        ASSERT_NE(c, nullptr) << sm;
        EXPECT_EQ(c->new_value, "'Outputs'");
    }
}

TEST(CorpusPairs, BpGesAddsAnEntryWithoutANewRevision) {
    ESI_REQUIRE_CORPUS();
    // RevisionNo 0 in both. 2020-03 maps a third entry #x1a00:#x3 'OverTemperatureTriggerBP' into
    // TxPdo 0x1A00, shrinks STRING(3) to STRING(0) for 0x1009/0x100A, sets PdoUpload="false", and
    // adds a second DataType DT1A00 and a second object 0x1A00 (duplicates: invalid per the XSD).
    const auto r =
        pair("ProjectMARCH__BP-GES__ethercat-slaves__2020-02.xml", "ProjectMARCH__BP-GES__ethercat-slaves__2020-03.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::breaking);
    EXPECT_EQ(r.error_count(), 1u);
    EXPECT_NE(at(r, ChangeKind::pdo_entry_added, "TxPdo[#x1A00]/Entry[#x1A00:03]"), nullptr);
    const esi::Change* size = at(r, ChangeKind::object_size_changed, "Dictionary/Object[#x1009]/BitSize");
    ASSERT_NE(size, nullptr);
    EXPECT_EQ(size->old_value, "24");
    EXPECT_EQ(size->new_value, "0");
    const esi::Change* upload = at(r, ChangeKind::mailbox_attribute_changed, "Mailbox/CoE@PdoUpload");
    ASSERT_NE(upload, nullptr);
    EXPECT_EQ(upload->change_class, ChangeClass::compatible);
    EXPECT_NE(at(r, ChangeKind::object_added, "Dictionary/Object[#x1A00]"), nullptr);  // the duplicate
}

TEST(CorpusPairs, Ek13xxOnlyAddsADevice) {
    ESI_REQUIRE_CORPUS();
    // 2018-06 adds EK1300 (#x05142C52); EK1310 and EK1322 are unchanged.
    const auto r = pair("Beckhoff__EK13xx__dls-ethercat__2018-01.xml", "Beckhoff__EK13xx__dls-ethercat__2018-06.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::compatible);
    ASSERT_EQ(r.changes.size(), 1u);
    EXPECT_EQ(r.changes[0].kind, ChangeKind::device_added);
    EXPECT_EQ(r.changes[0].device->product_code, 0x05142C52u);
}

TEST(CorpusPairs, El1xxxAddsARevisionAndUpdatesUrls) {
    ESI_REQUIRE_CORPUS();
    // 2011-08 adds EL1252 revision #x00130000 next to #x00110000/#x00120000 (ConfigData 0401400000000000
    // -> 0401000000000000) and changes URLs; nothing a configuration made from 2011-05 relies on.
    const auto r = pair("Beckhoff__EL1xxx__dls-ethercat__2011-05.xml", "Beckhoff__EL1xxx__dls-ethercat__2011-08.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::compatible);
    EXPECT_EQ(r.count(ChangeClass::breaking), 0u);
    const esi::Change* added = at(r, ChangeKind::device_revision_added, "Type@RevisionNo");
    ASSERT_NE(added, nullptr);
    EXPECT_EQ(added->device->product_code, 0x04E43052u);
    EXPECT_EQ(added->device->revision, 0x00130000u);
    EXPECT_EQ(added->device->compared_revision, 0x00120000u);
    EXPECT_EQ(count(r, ChangeKind::eeprom_config_data_changed), 1u);
    EXPECT_GT(count(r, ChangeKind::comment_changed), 50u);  // the URL updates
}

TEST(CorpusPairs, Ej1xxxAddsADeviceAndHideTypes) {
    ESI_REQUIRE_CORPUS();
    // 2018-06 adds EJ1819 (#x071B2852) and HideType elements (unmodelled) to five devices.
    const auto r = pair("Beckhoff__EJ1xxx__dls-ethercat__2016-12.xml", "Beckhoff__EJ1xxx__dls-ethercat__2018-06.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::compatible);
    EXPECT_EQ(count(r, ChangeKind::device_added), 1u);
    for (const auto& c : r.changes) {
        if (c.kind != ChangeKind::device_added) {
            EXPECT_EQ(c.kind, ChangeKind::extras_changed) << c.path;
        }
    }
}

TEST(CorpusPairs, FcxxxxAddsRevisionsAndAProduct) {
    ESI_REQUIRE_CORPUS();
    // 2016-12 keeps FC1100 #x00100000, adds FC1100 #x00110000 (with TxPdo 0x1A80 assigned to Sm 3,
    // DC modes, PdoAssign) and the new FC1121 (#x04610C62) in two revisions.
    const auto r = pair("Beckhoff__FCxxxx__dls-ethercat__2011-08.xml", "Beckhoff__FCxxxx__dls-ethercat__2016-12.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::compatible);
    const esi::Change* added = at(r, ChangeKind::device_revision_added, "Type@RevisionNo");
    ASSERT_NE(added, nullptr);
    EXPECT_EQ(added->device->revision, 0x00110000u);
    EXPECT_EQ(added->device->compared_revision, 0x00100000u);
    const esi::Change* pdo = at(r, ChangeKind::pdo_added_assigned, "TxPdo[#x1A80]");
    ASSERT_NE(pdo, nullptr);
    EXPECT_EQ(pdo->change_class, ChangeClass::compatible);  // the old revision is still described
    EXPECT_EQ(count(r, ChangeKind::device_added), 2u);
    EXPECT_EQ(count(r, ChangeKind::dc_op_mode_added), 2u);
}

TEST(CorpusPairs, Ek11xxAcrossRepositoriesOnlyAddsDevicesAndRevisions) {
    ESI_REQUIRE_CORPUS();
    const auto r = pair("Beckhoff__EK11xx__dls-ethercat.xml", "Beckhoff__EK11xx__ethercat-esi.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::compatible);
    EXPECT_EQ(count(r, ChangeKind::device_added), 1u);  // EK1121-0010
    EXPECT_EQ(count(r, ChangeKind::device_revision_added), 4u);
    EXPECT_EQ(r.error_count(), 0u);
}

TEST(CorpusPairs, HpMicroModulesLoseTheirProfileUnderTheSameRevision) {
    ESI_REQUIRE_CORPUS();
    // Product #x3 revision #x1 in both. 2025-12: Physics "YY" -> "YYY"; the three axis modules
    // (#x119800, #x219800, #x319800, all accepted by the device's slots) drop ProfileNo 402 and AddInfo 2.
    const auto r = pair("HPMicro__ECAT_CIA402__hpm_sdk__2024-09.xml", "HPMicro__ECAT_CIA402__hpm_sdk__2025-12.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::breaking);
    EXPECT_EQ(count(r, ChangeKind::profile_number_changed), 3u);
    EXPECT_NE(at(r, ChangeKind::profile_number_changed, "Modules/Module[#x00119800]/Profile/ProfileNo"), nullptr);
    const esi::Change* physics = at(r, ChangeKind::physics_ports_added, "@Physics");
    ASSERT_NE(physics, nullptr);
    EXPECT_EQ(physics->new_value, "'YYY'");
    const esi::Change* error = at(r, ChangeKind::revision_not_changed, "Type@RevisionNo");
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->device->product_code, 3u);
}

TEST(CorpusPairs, NeckOrbita3dGainsAMailboxUnderTheSameRevision) {
    ESI_REQUIRE_CORPUS();
    // Product #x1 revision #x1 in both. fw1.5 puts MBoxOut/MBoxIn in SM0/SM1 (process data moves to
    // SM2/SM3, a fourth Sm is added), adds a CoE/FoE mailbox and a BootStrap.
    const auto r = pair("PollenRobotics__NeckOrbita3d_fw1.0__poulpe.xml", "PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::breaking);
    EXPECT_EQ(r.error_count(), 1u);
    const esi::Change* sm0 = at(r, ChangeKind::sm_type_changed, "Sm[0]");
    ASSERT_NE(sm0, nullptr);
    EXPECT_EQ(sm0->old_value, "'OrbitaIn'");
    EXPECT_EQ(sm0->new_value, "'MBoxOut'");
    EXPECT_NE(at(r, ChangeKind::sm_added, "Sm[3]"), nullptr);
    EXPECT_NE(at(r, ChangeKind::mailbox_added, "Mailbox"), nullptr);
    EXPECT_NE(at(r, ChangeKind::eeprom_boot_strap_changed, "Eeprom/BootStrap"), nullptr);
    EXPECT_NE(at(r, ChangeKind::pdo_sm_changed, "RxPdo[#x1600]@Sm"), nullptr);
}

TEST(CorpusPairs, SomanetSingleFixesItsMappingUnderTheSameRevision) {
    ESI_REQUIRE_CORPUS();
    // Revision #x0A000002 in both. 2013 maps #x1600:01.. (the mapping object itself) into RxPdo
    // 0x1600; 2016 maps #x6040:00 …; EoE is gone; SM1 moves from #x1080 to #x1400.
    const auto r =
        pair("Synapticon__Somanet_CiA402-single__siitool__2013.xml", "Synapticon__Somanet_CiA402-single__siitool__2016.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::breaking);
    EXPECT_EQ(r.error_count(), 1u);
    EXPECT_NE(at(r, ChangeKind::mailbox_protocol_removed, "Mailbox/EoE"), nullptr);
    const esi::Change* entry = at(r, ChangeKind::pdo_entry_index_changed, "RxPdo[#x1600]/Entry[#x1600:01]/Index");
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->new_value->rfind("#x6040:00", 0), 0u) << *entry->new_value;
    const esi::Change* sm1 = at(r, ChangeKind::sm_address_changed, "Sm[1]@StartAddress");
    ASSERT_NE(sm1, nullptr);
    EXPECT_EQ(sm1->old_value, "#x1080");
    EXPECT_EQ(sm1->new_value, "#x1400");
}

TEST(CorpusPairs, SomanetCia402NarrowsAccessUnderTheSameRevision) {
    ESI_REQUIRE_CORPUS();
    // 2017-04 makes 0x6041 (Statusword) read-only (Access rw -> ro) and drops 0x2101 'Feedback Sensor 1'.
    const auto r = pair("Synapticon__SOMANET_CiA_402__sc_sncn_ethercat_drive__2017-01.xml",
                        "Synapticon__SOMANET_CiA_402__sc_sncn_ethercat_drive__2017-04.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::breaking);
    EXPECT_EQ(r.error_count(), 1u);
    const esi::Change* access = at(r, ChangeKind::object_access_narrowed, "Dictionary/Object[#x6041]/Flags/Access");
    ASSERT_NE(access, nullptr);
    EXPECT_EQ(access->old_value, "rw");
    EXPECT_EQ(access->new_value, "ro");
    EXPECT_NE(at(r, ChangeKind::object_removed, "Dictionary/Object[#x2101]"), nullptr);
}

TEST(CorpusPairs, CuxxxxCopyWithoutDictionariesRemovesObjects) {
    ESI_REQUIRE_CORPUS();
    // The hw_device_mgr copy keeps empty Dictionary elements (0 objects, against 77 in the
    // DiamondLightSource copy): every object is removed.
    const auto r = pair("Beckhoff__CUxxxx__dls-ethercat.xml", "Beckhoff__CUxxxx__hw_device_mgr.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::breaking);
    EXPECT_GT(count(r, ChangeKind::object_removed), 70u);
    EXPECT_EQ(count(r, ChangeKind::object_added), 0u);
    EXPECT_GE(r.error_count(), 1u);
}

TEST(CorpusPairs, EasyCatProjectsWithDifferentProductCodesAreRemovalAndAddition) {
    ESI_REQUIRE_CORPUS();
    // Both written by the EasyConfigurator: #xDEADBEEF (myCustomSlave) and #xABE00001 (TestEasyCAT_Custom).
    const auto r =
        pair("ABT__EasyCAT_myCustomSlave__dslemusp-EasyCAT.xml", "ABT__EasyCAT_TestEasyCAT_Custom__dslemusp-EasyCAT.xml");
    SCOPED_TRACE(listing(r));
    EXPECT_EQ(r.verdict, Verdict::breaking);
    const esi::Change* removed = nullptr;
    for (const auto& c : r.changes)
        if (c.kind == ChangeKind::device_removed) removed = &c;
    ASSERT_NE(removed, nullptr);
    EXPECT_EQ(removed->device->product_code, 0xDEADBEEFu);
    EXPECT_EQ(count(r, ChangeKind::device_added), 1u);
    EXPECT_EQ(r.error_count(), 0u);
}

TEST(CorpusPairs, EveryFileAgainstItselfIsIdentical) {
    ESI_REQUIRE_CORPUS();
    std::size_t compared = 0;
    for (const auto& entry : std::filesystem::directory_iterator(esi::test::corpus_esi_dir())) {
        if (entry.path().extension() != ".xml") continue;
        const esi::FileDiff diff = esi::diff_files(entry.path(), entry.path());
        if (!diff.result) continue;  // not well-formed (the manifest names one such file)
        ++compared;
        EXPECT_TRUE(diff.result->identical()) << entry.path().filename() << "\n" << listing(*diff.result);
    }
    EXPECT_GE(compared, 90u);
}

TEST(CorpusPairs, MalformedCorpusFileIsAReadError) {
    ESI_REQUIRE_CORPUS();
    const auto dir = esi::test::corpus_esi_dir();
    const esi::FileDiff diff = esi::diff_files(dir / "Synapticon__Somanet_CiA402-single__siitool__2015-02-malformed.xml",
                                               dir / "Synapticon__Somanet_CiA402-single__siitool__2016.xml");
    EXPECT_FALSE(diff.result.has_value());
    ASSERT_FALSE(diff.diagnostics.empty());
    EXPECT_EQ(diff.diagnostics.items()[0].rule, "xml-syntax");
    EXPECT_EQ(diff.diagnostics.items()[0].pos.line, 502u);  // xmllint: line 502, tag mismatch
}

}  // namespace
