// Real catalogue devices run from their ESI files alone on the emulated ESC, brought to OP frame by
// frame by the tests' master with their default PDOs: digital and analog terminals, couplers, CoE
// drives of several vendors, DC devices, modular devices with their default modules.

#include <gtest/gtest.h>

#include <map>

#include "esi/device_selector.hpp"
#include "sim_esc/line_master.hpp"
#include "sim_esc/line_session.hpp"
#include "sim_esc/sim_fixtures.hpp"
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
    {"Inovance__SV660_EOE_1Axis_V9.12__hw_device_mgr__2021-09.xml #x000C010D:#x00010000 (CoE drive (Inovance))",
     {0x001D,
      "ESI inconsistent: the Dictionary's 0x1C12 and 0x1C13 default to no entries (DefaultData 00) while RxPdo 0x1701 "
      "and TxPdo 0x1B01 name Sm 2 and 3; the master reads the empty assignment over CoE, falls back to the SII's PDOs "
      "(as SOEM does) and enables SM2 with 12 bytes, the firmware's assignment maps none (invalid output configuration)"}},
    {"Weidmueller__UR20_FBC__ethercat-esi.xml #x4F911C30:#x00011100 (modular coupler)",
     {0x001D,
      "ESI inconsistent: 0x1C12/0x1C13 and the mapping objects 0x16FF/0x1AFF default to no entries (a configuration "
      "tool downloads them with the module list), while the Mandatory RxPdo 0x16FF names Sm 2; the master falls back to "
      "the SII's PDOs and enables SM2 with 2 bytes, the firmware's assignment maps none (invalid output configuration)"}},
};

// Devices that reach OP without the process data their ESI declares, and why.
const std::map<std::string, const char*> known_without_process_data = {
    {"Elmo__ECAT_00010420_V11__hw_device_mgr.xml #x00030924:#x00000001 (CoE drive (Elmo))",
     "ESI defect: its own SyncM category (Eeprom/Category 41) has 9 bytes, one record for SM0 at 0x0000; the SII gives "
     "no start address for SM2/SM3, so the master maps no process data, and the firmware, whose SyncManager checks "
     "come from the same SII, expects none"},
    {"Elmo__ECAT_00010420_V11__hw_device_mgr.xml #x00030925:#x00000001 (CoE drive (Elmo))",
     "ESI defect: the same SyncM category as product 0x00030924"},
};

std::string label_of(const CorpusDevice& d) {
    return std::string(d.file) + " " + d.product_code + ":" + d.revision + " (" + d.kind + ")";
}

std::optional<ModelDevice> corpus_device(const CorpusDevice& c) {
    std::string error;
    const std::optional<DeviceSelector> selector = parse_device_selector(std::string(c.product_code) + ":" + c.revision, error);
    if (!selector) return std::nullopt;
    for (ModelDevice& d : model_devices(corpus_esi_dir() / c.file))
        if (selector->matches(*d.device)) return std::move(d);
    return std::nullopt;
}

TEST(LineCorpus, CatalogueDevicesReachOpWithTheirDefaultPdos) {
    ESI_REQUIRE_CORPUS();
    std::size_t at_op = 0;
    for (const CorpusDevice& c : corpus_devices) {
        const std::string label = label_of(c);
        SCOPED_TRACE(label);
        const std::optional<ModelDevice> d = corpus_device(c);
        ASSERT_TRUE(d) << "no such device in the corpus";
        std::string error;
        std::optional<sim::Line> line = device_line(*d, std::nullopt, false, error);
        ASSERT_TRUE(line) << error;
        LineMaster master(*line);
        ASSERT_TRUE(master.scan());
        std::size_t refused = 0;
        StateResult refusal;
        const bool op = master.to_op(&refused, &refusal);
        const auto known = known_not_op.find(label);
        if (known != known_not_op.end()) {
            EXPECT_FALSE(op) << "listed as not reaching OP (" << known->second.reason << "), but it does now";
            EXPECT_EQ(refusal.al_status_code, known->second.al_status_code)
                << "listed as refused with AL status code 0x" << std::hex << known->second.al_status_code << " ("
                << known->second.reason << "), refused with 0x" << refusal.al_status_code;
            EXPECT_TRUE(refusal.error()) << "the error indication";
            continue;
        }
        EXPECT_TRUE(op) << "AL status 0x" << std::hex << refusal.al_status << ", AL status code 0x" << refusal.al_status_code;
        if (!op) continue;
        ++at_op;
        const LineSlave& s = master.slaves[0];
        if (const auto without = known_without_process_data.find(label); without != known_without_process_data.end()) {
            EXPECT_EQ(s.output_bytes() + s.input_bytes(), 0u)
                << "listed as reaching OP without process data (" << without->second << "), but it has some now";
        } else if (d->output_bits + d->input_bits > 0) {
            // A device whose ESI assigns PDOs runs with process data (found over CoE or in the SII,
            // as a master finds them; the working counter below shows the firmware agrees).
            EXPECT_GT(s.output_bytes() + s.input_bytes(), 0u) << "in OP without process data";
        }
        // Without process data (a coupler) there is nothing to cycle.
        const std::uint16_t expected = static_cast<std::uint16_t>((s.output_bytes() ? 2 : 0) + (s.input_bytes() ? 1 : 0));
        if (expected == 0) continue;
        unsigned wkc_ok = 0;
        for (unsigned cycle = 0; cycle < 100; ++cycle) {
            const auto a = master.cycle(std::vector<std::uint8_t>(master.output_image_bytes(), 0));
            if (a && a->working_counter == expected) ++wkc_ok;
        }
        EXPECT_EQ(wkc_ok, 100u) << "expected working counter " << expected;
        EXPECT_EQ(master.state_of(s).al_status, 8);
    }
    EXPECT_GE(at_op, 25u);
}

}  // namespace
}  // namespace esi::test
