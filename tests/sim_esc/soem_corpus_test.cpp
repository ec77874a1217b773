// Real catalogue devices run from their ESI files alone through esi-sim, brought to OP by SOEM 2.x
// with their default PDOs: digital and analog terminals, couplers, CoE drives of several vendors,
// DC devices, modular devices with their default modules.

#include <gtest/gtest.h>

#include <iostream>
#include <map>

#include "sim_esc/sim_fixtures.hpp"
#include "sim_esc/soem_session.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

struct CorpusDevice {
    const char* file;
    const char* product_code;
    const char* revision;
    const char* kind;
};

const CorpusDevice corpus_devices[] = {
    {"Beckhoff__EL1xxx__dls-ethercat__2011-08.xml", "#x03ea3052", "#x00100000", "digital input"},
    {"Beckhoff__EL1xxx__dls-ethercat__2011-08.xml", "#x03f03052", "#x00100000", "digital input"},
    {"Beckhoff__EL1xxx__dls-ethercat__2011-08.xml", "#x03fa3052", "#x00100000", "digital input"},
    {"Beckhoff__EL1xxx__dls-ethercat__2011-08.xml", "#x07113052", "#x00100000", "digital input"},
    {"Beckhoff__EL2xxx__dls-ethercat.xml", "#x07d43052", "#x00120000", "digital output"},
    {"Beckhoff__EL2xxx__dls-ethercat.xml", "#x07d83052", "#x00120000", "digital output"},
    {"Beckhoff__EL2xxx__dls-ethercat.xml", "#x0AF93052", "#x00120000", "digital output"},
    {"Beckhoff__EL3xxx__dls-ethercat.xml", "#xe123052", "#x00130000", "analog input"},
    {"Beckhoff__EL4xxx__dls-ethercat__2013-03.xml", "#xfa23052", "#x00110000", "analog output"},
    {"Beckhoff__EL4xxx__dls-ethercat__2013-03.xml", "#x10243052", "#x03fA0000", "analog output"},
    {"Beckhoff__EL15xx__dls-ethercat.xml", "#x05de3052", "#x00160000", "counter"},
    {"Beckhoff__EL9xxx__dls-ethercat__2018-01.xml", "#x23963052", "#x00120000", "power terminal"},
    {"Beckhoff__EL47xx__dls-ethercat.xml", "#x12683052", "#x00010000", "analog output, DC"},
    {"Beckhoff__EK11xx__dls-ethercat.xml", "#x044c2c52", "#x00120000", "coupler"},
    {"Beckhoff__EK11xx__dls-ethercat.xml", "#x04562c52", "#x00110000", "coupler extension"},
    {"Beckhoff__EJ7xxx__dls-ethercat.xml", "#x1b872852", "#x00130000", "stepper drive, DC"},
    {"Elmo__ECAT_00010420_V11__hw_device_mgr.xml", "#x00030924", "#x00000001", "CoE drive (Elmo)"},
    {"Elmo__ECAT_00010420_V11__hw_device_mgr.xml", "#x00030925", "#x00000001", "CoE drive (Elmo)"},
    {"Copley__XE2_4.60__EtherCAT-ESI-File-Examples__b.xml", "#x10b0", "#x00010004", "CoE drive (Copley)"},
    {"Synapticon__Somanet_CiA402-single__siitool__2016.xml", "#x00000201", "#x0a000002", "CoE drive (Synapticon)"},
    {"HPMicro__ECAT_CIA402__hpm_sdk__2025-12.xml", "#x00000003", "#x00000001", "CoE drive (HPMicro)"},
    {"Inovance__SV660_EOE_1Axis_V9.12__hw_device_mgr__2021-09.xml", "#x000C010D", "#x00010000", "CoE drive (Inovance)"},
    {"HPMicro__ECAT_IO__hpm_sdk.xml", "#x00000001", "#x00000001", "digital I/O (SSC)"},
    {"SOES__linux_lan9252demo__soes.xml", "1234", "0", "digital I/O (SOES)"},
    {"SOES__rtl_xmc4_dynpdo__soes.xml", "#x4800", "0", "dynamic PDO (SOES)"},
    {"SOES__xmc4300_slavedemo_esi__soes.xml", "#x12783456", "#x00000001", "sample application (SOES)"},
    {"SOES__tiesc_am335x__soes.xml", "#x9876", "0", "digital I/O (SOES)"},
    {"MetalMusings__Dig_8IN_8OUT__MyOwnEtherCATDevice.xml", "#x0000000d", "#x00000001", "digital I/O (LAN9252)"},
    {"ABT__EasyCAT_V2_0__soes.xml", "#x00DEFEDE", "#x00005A00", "I/O board (EasyCAT)"},
    {"ASIX__AX58100_EVB_DIO__MyOwnEtherCATDevice.xml", "#x00010200", "#x00000001", "digital I/O (AX58100)"},
    {"EtherBerry__EtherBerry__soes.xml", "#x00001010", "#x00000008", "I/O board (EtherBerry)"},
    {"ETG__ModulesSlots_CiA402__siitool.xml", "#x10000", "#x0", "modular drive"},
    {"Weidmueller__UR20_FBC__ethercat-esi.xml", "#x4F911C30", "#x00011100", "modular coupler"},
    {"NationalInstruments__NI9144__dls-ethercat.xml", "#x23B8", "2", "modular chassis"},
};

// Devices that do not reach OP: the AL status code the firmware refuses with, and why. Each is
// an inconsistency of the ESI that a device built from it would show as well.
// The label is the one the test prints: FILE PRODUCTCODE:REVISION (KIND).
struct Refusal {
    unsigned al_status_code;
    const char* reason;
};

const std::map<std::string, Refusal> known_not_op = {
    {"Elmo__ECAT_00010420_V11__hw_device_mgr.xml #x00030924:#x00000001 (CoE drive (Elmo))",
     {0x0016,
      "ESI defect: its own SyncM category (Eeprom/Category 41) has 9 bytes and puts SM0 at 0x0000; SOEM falls back to "
      "0x1000/128 bytes and the firmware refuses that mailbox (invalid mailbox configuration), as the device would "
      "with this image"}},
    {"Elmo__ECAT_00010420_V11__hw_device_mgr.xml #x00030925:#x00000001 (CoE drive (Elmo))",
     {0x0016, "ESI defect: the same SyncM category as product 0x00030924"}},
    {"Inovance__SV660_EOE_1Axis_V9.12__hw_device_mgr__2021-09.xml #x000C010D:#x00010000 (CoE drive (Inovance))",
     {0x001D,
      "ESI inconsistent: the Dictionary's 0x1C12 and 0x1C13 default to no entries (DefaultData 00) while RxPdo 0x1701 "
      "and TxPdo 0x1B01 name Sm 2 and 3; SOEM reads the empty 0x1C12 over CoE, falls back to the SII's PDOs and "
      "enables SM2 with 12 bytes, the firmware's assignment maps none (invalid output configuration)"}},
    {"Weidmueller__UR20_FBC__ethercat-esi.xml #x4F911C30:#x00011100 (modular coupler)",
     {0x001D,
      "ESI inconsistent: 0x1C12/0x1C13 and the mapping objects 0x16FF/0x1AFF default to no entries (a configuration "
      "tool downloads them with the module list), while the Mandatory RxPdo 0x16FF names Sm 2; SOEM falls back to the "
      "SII's PDOs and enables SM2 with 2 bytes, the firmware's assignment maps none (invalid output configuration)"}},
    {"NationalInstruments__NI9144__dls-ethercat.xml #x23B8:2 (modular chassis)",
     {0x001D,
      "ESI inconsistent: the Outputs SM (SM2) has DefaultSize 0x200 and Enable 1, but the device has no RxPdo; SOEM, "
      "given no output PDO, keeps the SII's 512-byte SM2 enabled, and the firmware refuses an output SM whose length "
      "is not that of its PDOs, 0 bytes (invalid output configuration; SOES's ESC_checkSM23 makes the same check)"}},
};

std::string label_of(const CorpusDevice& d) {
    return std::string(d.file) + " " + d.product_code + ":" + d.revision + " (" + d.kind + ")";
}

TEST(SoemCorpus, CatalogueDevicesReachOpWithTheirDefaultPdos) {
    ESI_REQUIRE_CORPUS();
    ESI_REQUIRE_SOEM();
    std::vector<SoemStep> steps;
    for (const CorpusDevice& d : corpus_devices) {
        // A device known not to reach OP gets a short wait: its refusal comes at once.
        const char* wait = known_not_op.count(label_of(d)) ? "300" : "1500";
        steps.push_back({{(corpus_esi_dir() / d.file).string(), "--device", std::string(d.product_code) + ":" + d.revision},
                         {"--cycles", "100", "--dc", "--state-timeout-ms", wait}});
    }
    const auto results = run_soem_session(steps);
    ASSERT_EQ(results.size(), std::size(corpus_devices));
    std::size_t at_op = 0;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const CorpusDevice& d = corpus_devices[i];
        const std::string label = label_of(d);
        SCOPED_TRACE(label);
        ASSERT_TRUE(results[i].report) << results[i].sim_stderr << results[i].master_output;
        const auto& r = *results[i].report;
        ASSERT_EQ(r["slaves"], 1) << results[i].sim_stderr;
        const auto& s = r["slave"][0];
        const auto known = known_not_op.find(label);
        if (known != known_not_op.end()) {
            EXPECT_EQ(r["op"], false) << "listed as not reaching OP (" << known->second.reason << "), but it does now";
            EXPECT_EQ(s["al_status_code"], known->second.al_status_code)
                << "listed as refused with AL status code 0x" << std::hex << known->second.al_status_code << " ("
                << known->second.reason << "), refused with " << s["al_status_text"];
            // A mailbox refusal leaves the slave in INIT, a process-data refusal in PREOP.
            EXPECT_EQ(s["state"].get<unsigned>() & 0x0F, known->second.al_status_code == 0x0016 ? 1u : 2u);
            EXPECT_NE(s["state"].get<unsigned>() & 0x10, 0u) << "the error indication";
            continue;
        }
        EXPECT_EQ(r["op"], true) << "state " << s["state"] << ", AL status code " << s["al_status_code"] << " "
                                 << s["al_status_text"] << "\n" << results[i].sim_stderr;
        // Without process data (a coupler) SOEM sends no cyclic frame: no working counter to check.
        if (r["expected_wkc"] != 0) {
            EXPECT_EQ(r["wkc_ok"], r["cycles"]) << "expected working counter " << r["expected_wkc"];
        }
        if (r["op"] == true) ++at_op;
        if (r["op"] != true || (r["expected_wkc"] != 0 && r["wkc_ok"] != r["cycles"]))
            std::cout << "not at OP: " << label << ": state " << s["state"] << ", AL status code " << s["al_status_code"]
                      << ", working counter " << r["wkc_ok"] << "/" << r["cycles"] << " (expected " << r["expected_wkc"]
                      << ")\n";
    }
    EXPECT_GE(at_op, 25u);
}

}  // namespace
}  // namespace esi::test
