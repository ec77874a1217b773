// The sample device sources: each loads without a single diagnostic, and the derived model says
// what the seed manuals say.

#include <gtest/gtest.h>

#include <cctype>


#include "esi/check/effective_config.hpp"
#include "esi/lint/lint.hpp"
#include "yaml/yaml_test_support.hpp"

using namespace esi;
using esi::test::default_of;
using esi::test::describe;
using esi::test::only_device;
using esi::test::sample_path;

namespace {

const char* const samples[] = {"servo-item-c-series.yaml", "inverter-stoeber-mds5000.yaml", "encoder-tr-linear.yaml",
                               "digital-io-8.yaml", "modular-coupler.yaml"};

DeviceSource load_sample(const std::string& name) {
    DeviceSource s = load_device_source_file(sample_path(name));
    EXPECT_TRUE(s.diagnostics.empty()) << name << ":\n" << describe(s.diagnostics);
    EXPECT_TRUE(s.document.has_value()) << name;
    return s;
}

const Pdo& pdo(const Device& d, std::uint32_t index) {
    const Pdo* p = d.find_pdo(index);
    if (!p) throw std::runtime_error("no PDO " + std::to_string(index));
    return *p;
}

}  // namespace

TEST(YamlSamples, EveryDirectoryEntryIsTested) {
    std::set<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(esi::test::source_dir() / "samples"))
        if (e.path().extension() == ".yaml") files.insert(e.path().filename().string());
    std::set<std::string> tested(std::begin(samples), std::end(samples));
    EXPECT_EQ(files, tested);
}

TEST(YamlSamples, LoadWithoutDiagnostics) {
    for (const char* name : samples) {
        SCOPED_TRACE(name);
        const DeviceSource s = load_sample(name);
        ASSERT_TRUE(s.document);
        EXPECT_EQ(s.document->kind, DocumentKind::ethercat_info);
        EXPECT_EQ(s.document->path, sample_path(name).string());
    }
}

TEST(YamlSamples, SeedDevicesDeclareTheirLimitsAndTheRulesFindNothing) {
    for (const char* name : samples) {
        SCOPED_TRACE(name);
        const DeviceSource s = load_sample(name);
        ASSERT_TRUE(s.document);
        EffectiveConfig config;
        for (const auto& [selector, limits] : s.device_limits)
            config.device_limits.emplace_back(std::vector<std::uint32_t>{selector.product_code}, limits);
        const Diagnostics found = run_rules(*s.document, config);
        EXPECT_EQ(found.count(Severity::error) + found.count(Severity::warning), 0u) << describe(found);
    }
    // The seed devices carry their manuals' limits.
    for (const char* name : {"servo-item-c-series.yaml", "inverter-stoeber-mds5000.yaml", "encoder-tr-linear.yaml"}) {
        const DeviceSource s = load_sample(name);
        ASSERT_EQ(s.device_limits.size(), 1u) << name;
        EXPECT_FALSE(s.device_limits[0].second.empty()) << name;
        EXPECT_EQ(s.device_limits[0].first.product_code, only_device(s).type.product_code.value_or(0)) << name;
    }
}

TEST(YamlSamples, ServoFollowsTheItemAfagManuals) {
    const DeviceSource s = load_sample("servo-item-c-series.yaml");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    EXPECT_EQ(s.document->infos[0].vendor->id, 0xE4u);
    EXPECT_EQ(d.type.product_code, 0x264860D2u);
    EXPECT_EQ(d.type.revision_no, 0x20000u);

    // SM0/SM1 mailbox, SM2 outputs, SM3 inputs (§6.1.1), sized from the default PDOs.
    ASSERT_EQ(d.sms.size(), 4u);
    EXPECT_EQ(d.sms[0].type, "MBoxOut");
    EXPECT_EQ(d.sms[1].type, "MBoxIn");
    EXPECT_EQ(d.sms[2].type, "Outputs");
    EXPECT_EQ(d.sms[3].type, "Inputs");
    EXPECT_EQ(d.sms[0].start_address, 0x1000u);
    EXPECT_EQ(d.sms[1].start_address, 0x1080u);
    EXPECT_EQ(d.sms[0].control_byte, 0x26u);
    EXPECT_EQ(d.sms[1].control_byte, 0x22u);
    EXPECT_EQ(d.sms[2].default_size, 3u + 4u + 4u + 2u);
    EXPECT_EQ(d.sms[3].default_size, 3u + 4u + 4u + 2u);

    // 4 RxPDOs 0x1600-0x1603 "Outputs" on SM2, 4 TxPDOs 0x1A00-0x1A03 "Inputs" on SM3.
    ASSERT_EQ(d.rx_pdos.size(), 4u);
    ASSERT_EQ(d.tx_pdos.size(), 4u);
    for (std::uint32_t i = 0; i < 4; ++i) {
        EXPECT_EQ(d.rx_pdos[i].index, 0x1600u + i);
        EXPECT_EQ(d.tx_pdos[i].index, 0x1A00u + i);
        EXPECT_EQ(primary_text(d.rx_pdos[i].names), "Outputs");
        EXPECT_EQ(primary_text(d.tx_pdos[i].names), "Inputs");
        EXPECT_EQ(d.rx_pdos[i].sm, 2u);
        EXPECT_EQ(d.tx_pdos[i].sm, 3u);
        for (const auto* list : {&d.rx_pdos, &d.tx_pdos})
            for (const auto& e : (*list)[i].entries) EXPECT_TRUE(e.bit_len == 8 || e.bit_len == 16 || e.bit_len == 32);
    }
    // The manual's RxPDO example: Controlword then Modes of operation, typed by the objects.
    const Pdo& rx = pdo(d, 0x1600);
    ASSERT_EQ(rx.entries.size(), 2u);
    EXPECT_EQ(rx.entries[0].index, 0x6040u);
    EXPECT_EQ(rx.entries[0].bit_len, 16u);
    EXPECT_EQ(rx.entries[0].data_type, "UINT");
    EXPECT_EQ(primary_text(rx.entries[0].names), "Controlword");
    EXPECT_EQ(rx.entries[1].index, 0x6060u);
    EXPECT_EQ(rx.entries[1].bit_len, 8u);
    EXPECT_EQ(rx.entries[1].data_type, "SINT");

    // The CoE element of §7 (DS402Channels, EdsFile, PdoAssign): services SDO, PDO and emergency
    // (§6.1), no SDO Information.
    ASSERT_TRUE(d.mailbox && d.mailbox->coe);
    EXPECT_FALSE(d.mailbox->coe->sdo_info.value_or(false));
    EXPECT_TRUE(d.mailbox->coe->pdo_assign.value_or(false));
    EXPECT_EQ(d.mailbox->coe->ds402_channels, 1);

    // The ESC20 has DC (Tabelle 4): SYNC0-synchronous, and frame-synchronous without DC (§6.8).
    ASSERT_TRUE(d.dc);
    ASSERT_EQ(d.dc->op_modes.size(), 2u);
    EXPECT_EQ(d.dc->op_modes[0].assign_activate, 0x0000u);
    EXPECT_EQ(d.dc->op_modes[1].assign_activate, 0x0300u);
    ASSERT_TRUE(d.dc->op_modes[1].cycle_time_sync0.has_value());
    EXPECT_EQ(d.dc->op_modes[1].cycle_time_sync0->factor, 1);

    // The InitCmds of §6.7.4 and §7 at PS, with data typed by the object.
    const auto& cmds = d.mailbox->coe->init_cmds;
    ASSERT_EQ(cmds.size(), 2u);
    EXPECT_EQ(cmds[0].transitions.at(0).text, "PS");
    EXPECT_EQ(cmds[0].index, 0x6040u);
    EXPECT_EQ(cmds[0].data.text, "0000");
    EXPECT_EQ(cmds[1].index, 0x6060u);
    EXPECT_EQ(cmds[1].subindex, 0u);
    EXPECT_EQ(cmds[1].data.text, "03");  // "velocity mode" by its enumeration text

    // Unsupported objects are left out; 0x1100 and 0x1C10/0x1C11 are there; derived objects too.
    const Dictionary* od = d.dictionary();
    ASSERT_TRUE(od);
    for (std::uint32_t absent : {0x1008u, 0x1009u, 0x100Au, 0x6089u, 0x608Au, 0x608Bu, 0x608Cu, 0x608Du, 0x608Eu})
        EXPECT_EQ(od->find_object(absent), nullptr) << std::hex << absent;
    for (std::uint32_t present : {0x1000u, 0x1018u, 0x1100u, 0x1600u, 0x1603u, 0x1A00u, 0x1A03u, 0x1C00u, 0x1C10u, 0x1C11u, 0x1C12u,
                                  0x1C13u, 0x6040u, 0x6060u})
        EXPECT_NE(od->find_object(present), nullptr) << std::hex << present;
    EXPECT_EQ(default_of(d, 0x1000, 0), 0x00020192u);
    EXPECT_EQ(default_of(d, 0x1018, 1), 0xE4u);
    EXPECT_EQ(default_of(d, 0x1018, 2), 0x264860D2u);
    EXPECT_EQ(default_of(d, 0x1018, 3), 0x20000u);
    EXPECT_EQ(default_of(d, 0x1C00, 3), 3u);
    EXPECT_EQ(default_of(d, 0x1C00, 4), 4u);
    EXPECT_EQ(default_of(d, 0x1C12, 0), 4u);
    EXPECT_EQ(default_of(d, 0x1C12, 1), 0x1600u);
    EXPECT_EQ(default_of(d, 0x1C13, 4), 0x1A03u);
    EXPECT_EQ(default_of(d, 0x1600, 1), 0x60400010u);  // mapping entry: index<<16 | sub<<8 | bits
    EXPECT_EQ(default_of(d, 0x1600, 2), 0x60600008u);
    // Objects are sorted ascending (SOES SDO_findobject needs it).
    for (std::size_t i = 1; i < od->objects.size(); ++i) EXPECT_LT(od->objects[i - 1].index, od->objects[i].index);
}

TEST(YamlSamples, InverterPlacesParametersByTheStoeberRule) {
    const DeviceSource s = load_sample("inverter-stoeber-mds5000.yaml");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    // [002 §7.2.4]: index = 0x2000 + 0x200 * (group - 1) + line, for every object named "A180 …".
    int checked = 0;
    for (const auto& o : d.dictionary()->objects) {
        // Names that start with a coordinate: a group letter, the line number, a blank.
        const std::string name = primary_text(o.names);
        std::size_t digits = 1;
        while (digits < name.size() && std::isdigit(static_cast<unsigned char>(name[digits]))) ++digits;
        if (name.size() < 3 || name[0] < 'A' || name[0] > 'Z' || digits == 1 || digits >= name.size() || name[digits] != ' ') continue;
        const unsigned group = static_cast<unsigned>(name[0] - 'A' + 1);
        const unsigned line = static_cast<unsigned>(std::stoul(name.substr(1, digits - 1)));
        EXPECT_EQ(o.index, 0x2000u + 0x200u * (group - 1) + line) << name;
        ++checked;
    }
    EXPECT_GE(checked, 14);

    // 4 PDOs a direction, at most 6 entries each; mapping objects offer 6 entries.
    EXPECT_EQ(d.rx_pdos.size(), 4u);
    EXPECT_EQ(d.tx_pdos.size(), 4u);
    for (const auto* list : {&d.rx_pdos, &d.tx_pdos})
        for (const auto& p : *list) {
            EXPECT_LE(p.entries.size(), 6u);
            EXPECT_EQ(default_of(d, p.index, 0), p.entries.size());
            ObjectLayout layout;
            EXPECT_NE(esi::test::object_entry(d, p.index, 6, layout), nullptr) << std::hex << p.index;
            EXPECT_EQ(esi::test::object_entry(d, p.index, 7, layout), nullptr) << std::hex << p.index;
        }
    // Default process data: A180 D230 C230 (5 bytes) / E200 D200 E100 E02 (7 bytes); A252/A253
    // assign PDO1 and PDO2, PDO3/PDO4 need POSITool blocks.
    EXPECT_EQ(d.sms[2].default_size, 5u);
    EXPECT_EQ(d.sms[3].default_size, 7u);
    EXPECT_EQ(pdo(d, 0x1600).sm, 2u);
    EXPECT_EQ(pdo(d, 0x1601).sm, 2u);
    EXPECT_FALSE(pdo(d, 0x1602).sm.has_value());
    EXPECT_FALSE(pdo(d, 0x1A03).sm.has_value());
    EXPECT_EQ(default_of(d, 0x1600, 1), 0x20B40008u);  // the derived entries of the digest §3.3.6
    EXPECT_EQ(default_of(d, 0x1600, 2), 0x26E60010u);
    EXPECT_EQ(default_of(d, 0x1A00, 1), 0x28C80008u);
    EXPECT_EQ(default_of(d, 0x1A00, 4), 0x28020010u);
    EXPECT_EQ(default_of(d, 0x20FC, 0), 0x1600u);  // A252.0 holds the first PDO, not a count
    EXPECT_EQ(default_of(d, 0x1C12, 0), 2u);
    EXPECT_EQ(default_of(d, 0x1C12, 2), 0x1601u);
    EXPECT_EQ(default_of(d, 0x1C12, 3), 0u);

    // DC op modes with the multiplier variants [002 §11.5].
    ASSERT_TRUE(d.dc);
    // Free run (A262.0/A263.0 "0: Not synchronized", [002 §10.1]) and the two DC modes of §11.5.
    ASSERT_EQ(d.dc->op_modes.size(), 3u);
    EXPECT_EQ(d.dc->op_modes[0].name, "FreeRun");
    EXPECT_EQ(d.dc->op_modes[0].assign_activate, 0x0000u);
    EXPECT_FALSE(d.dc->op_modes[0].cycle_time_sync0.has_value());
    EXPECT_EQ(d.dc->op_modes[1].cycle_time_sync0->factor, 1);
    EXPECT_EQ(d.dc->op_modes[2].cycle_time_sync0->factor, 2);
    EXPECT_EQ(d.dc->op_modes[2].assign_activate, 0x0300u);
    EXPECT_EQ(d.dc->op_modes[2].desc, "DC enabled (multiplier = 2)");
    // CoE and VoE ("POSITool over EtherCAT").
    ASSERT_TRUE(d.mailbox);
    EXPECT_TRUE(d.mailbox->coe && d.mailbox->voe);
    EXPECT_FALSE(d.mailbox->foe || d.mailbox->eoe || d.mailbox->soe);
    EXPECT_EQ(s.device_limits[0].second.max_entries_per_pdo, 6u);
}

TEST(YamlSamples, EncoderMapsPositionValueIntoTheFirstTxPdo) {
    const DeviceSource s = load_sample("encoder-tr-linear.yaml");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    EXPECT_EQ(default_of(d, 0x1000, 0), 406u);
    EXPECT_TRUE(d.rx_pdos.empty());
    const Pdo& tx = pdo(d, 0x1A00);
    ASSERT_EQ(tx.entries.size(), 1u);
    EXPECT_EQ(tx.entries[0].index, 0x6004u);
    EXPECT_EQ(tx.entries[0].bit_len, 32u);
    EXPECT_EQ(tx.entries[0].data_type, "UDINT");
    EXPECT_EQ(default_of(d, 0x1A00, 1), 0x60040020u);
    EXPECT_EQ(d.sms[3].default_size, 4u);
    // No outputs: SM2 is disabled, and no Outputs FMMU.
    EXPECT_EQ(d.sms[2].enable, 0u);
    for (const auto& f : d.fmmus) EXPECT_NE(f.type, "Outputs");
    EXPECT_EQ(d.dictionary()->find_object(0x1C12), nullptr);
    EXPECT_NE(d.dictionary()->find_object(0x1C13), nullptr);
}

TEST(YamlSamples, DigitalIoIsTheShortCommonCase) {
    const DeviceSource s = load_sample("digital-io-8.yaml");
    ASSERT_TRUE(s.document);
    const Device& d = only_device(s);
    const Pdo& rx = pdo(d, 0x1600);
    ASSERT_EQ(rx.entries.size(), 8u);
    for (std::uint32_t i = 0; i < 8; ++i) {
        EXPECT_EQ(rx.entries[i].subindex, i + 1);
        EXPECT_EQ(rx.entries[i].bit_len, 1u);
        EXPECT_EQ(rx.entries[i].data_type, "BOOL");
    }
    EXPECT_EQ(d.sms[2].default_size, 1u);
    EXPECT_EQ(d.sms[3].default_size, 1u);
    ASSERT_TRUE(d.eeprom && d.eeprom->boot_strap);
    EXPECT_EQ(d.eeprom->boot_strap->text, "0010800080108000");
    EXPECT_EQ(d.eeprom->byte_size, 2048u);
    // Names in two languages; the enumeration default given by its text.
    ASSERT_EQ(d.names.size(), 2u);
    EXPECT_EQ(d.names[1].lcid, 1031u);
    EXPECT_EQ(default_of(d, 0x8000, 0), 3u);
    // Every type the dictionary names is declared (ETG schema keyrefs).
    const Dictionary* od = d.dictionary();
    for (const char* t : {"BOOL", "USINT", "UINT", "UDINT"}) EXPECT_NE(od->find_data_type(t), nullptr) << t;
}

TEST(YamlSamples, ModularCouplerHasModulesAndSlots) {
    const DeviceSource s = load_sample("modular-coupler.yaml");
    ASSERT_TRUE(s.document);
    const EtherCATInfo& info = s.document->infos[0];
    ASSERT_EQ(info.modules.size(), 3u);
    const Device& d = info.devices[0];
    ASSERT_TRUE(d.slots);
    EXPECT_EQ(d.slots->max_slot_count, 4u);
    EXPECT_EQ(d.slots->slot_index_increment, 0x10u);
    ASSERT_EQ(d.slots->slots.size(), 4u);
    ASSERT_EQ(d.slots->slots[0].module_idents.size(), 3u);
    EXPECT_EQ(d.slots->slots[0].module_idents[2].value, 0x00010003u);
    EXPECT_EQ(d.slots->slots[0].default_ident, 0x00010001u);
    EXPECT_EQ(d.slots->slots[1].default_ident, 0x00010002u);

    const Module& ai = info.modules[2];
    EXPECT_EQ(ai.module_ident, 0x00010003u);
    ASSERT_EQ(ai.tx_pdos.size(), 1u);
    EXPECT_EQ(ai.tx_pdos[0].sm, 3u);
    EXPECT_TRUE(ai.tx_pdos[0].index_depend_on_slot.value_or(false));
    ASSERT_EQ(ai.tx_pdos[0].entries.size(), 2u);
    EXPECT_EQ(ai.tx_pdos[0].entries[1].bit_len, 16u);
    EXPECT_EQ(ai.tx_pdos[0].entries[1].data_type, "INT");
    ASSERT_TRUE(ai.profile && ai.profile->dictionary);
    EXPECT_NE(ai.profile->dictionary->find_data_type("INT"), nullptr);
    ASSERT_NE(ai.profile->dictionary->find_object(0x6000), nullptr);
    EXPECT_TRUE(ai.profile->dictionary->find_object(0x6000)->index_depend_on_slot.value_or(false));
    // The coupler's own PD SMs stay enabled for the modules' data.
    EXPECT_EQ(d.sms[2].enable, 1u);
    EXPECT_EQ(d.sms[3].enable, 1u);
}

TEST(YamlSamples, LoadingIsDeterministic) {
    for (const char* name : samples) {
        const DeviceSource a = load_sample(name);
        const DeviceSource b = load_sample(name);
        ASSERT_TRUE(a.document && b.document);
        const Device& da = a.document->infos[0].devices[0];
        const Device& db = b.document->infos[0].devices[0];
        ASSERT_EQ(da.dictionary() != nullptr, db.dictionary() != nullptr);
        if (!da.dictionary()) continue;
        ASSERT_EQ(da.dictionary()->objects.size(), db.dictionary()->objects.size());
        for (std::size_t i = 0; i < da.dictionary()->objects.size(); ++i)
            EXPECT_EQ(da.dictionary()->objects[i].type, db.dictionary()->objects[i].type);
        ASSERT_EQ(da.dictionary()->data_types.size(), db.dictionary()->data_types.size());
        for (std::size_t i = 0; i < da.dictionary()->data_types.size(); ++i)
            EXPECT_EQ(da.dictionary()->data_types[i].name, db.dictionary()->data_types[i].name);
    }
}

// ---- with the ESI writer ---------------------------------------------------------------------

#include "esi/lint/xsd.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"

namespace {

EffectiveConfig config_with_limits(const DeviceSource& s) {
    EffectiveConfig config;
    for (const auto& [selector, limits] : s.device_limits)
        config.device_limits.emplace_back(std::vector<std::uint32_t>{selector.product_code}, limits);
    return config;
}

}  // namespace

TEST(YamlSamples, WrittenEsiIsByteIdenticalOnReRun) {
    for (const char* name : samples) {
        SCOPED_TRACE(name);
        const DeviceSource a = load_sample(name);
        const DeviceSource b = load_sample(name);
        ASSERT_TRUE(a.document && b.document);
        const std::string xml = write_esi(*a.document);
        EXPECT_EQ(xml, write_esi(*b.document));
        EXPECT_NE(xml.find("<EtherCATInfo"), std::string::npos);
    }
}

TEST(YamlSamples, WrittenEsiValidatesAgainstTheEtgSchema) {
    ESI_REQUIRE_CORPUS();
    Diagnostics load_problems;
    const auto schemas =
        SchemaSet::load(esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022", load_problems);
    ASSERT_TRUE(schemas) << describe(load_problems);
    for (const char* name : samples) {
        SCOPED_TRACE(name);
        const DeviceSource s = load_sample(name);
        ASSERT_TRUE(s.document);
        const SourceText xml(std::string(name) + ".xml", write_esi(*s.document));
        const Diagnostics problems = schemas->validate(xml);
        EXPECT_TRUE(problems.empty()) << describe(problems) << "\n" << xml.text().substr(0, 4000);
    }
}

TEST(YamlSamples, EsiLintFindsNothingInTheWrittenEsi) {
    for (const char* name : samples) {
        SCOPED_TRACE(name);
        const DeviceSource s = load_sample(name);
        ASSERT_TRUE(s.document);
        const std::string xml = write_esi(*s.document);
        const ReadResult back = read_esi(xml, std::string(name) + ".xml");
        ASSERT_TRUE(back.document) << describe(back.diagnostics);
        EXPECT_TRUE(back.diagnostics.empty()) << describe(back.diagnostics);
        const Diagnostics found = run_rules(*back.document, config_with_limits(s));
        EXPECT_EQ(found.count(Severity::error) + found.count(Severity::warning), 0u) << describe(found);
    }
}

TEST(YamlSamples, TheSeedLimitsAreEnforced) {
    // The servo manuals allow four RxPDOs (§6.1.1) and BitLen 8/16/32 (Tabelle 14): a fifth PDO
    // and a BOOL entry break the limits the sample declares.
    std::string text = esi::test::read_text(sample_path("servo-item-c-series.yaml"));
    const std::string anchor = "      - { index: 0x1603, name: Outputs, fixed: true, entries: [0x6071] }\n";
    ASSERT_NE(text.find(anchor), std::string::npos);
    text.insert(text.find(anchor) + anchor.size(),
                "      - { index: 0x1604, name: Outputs, fixed: true, assigned: false, entries: [{ object: 0x6040, bit_len: 16 }, pad1] }\n");
    const DeviceSource s = esi::test::load_yaml(text, "servo.yaml");
    ASSERT_TRUE(s.document) << describe(s.diagnostics);
    const Diagnostics found = run_rules(*s.document, config_with_limits(s));
    std::set<std::string> rules;
    for (const auto& d : found)
        if (d.severity == Severity::error) rules.insert(d.rule);
    EXPECT_TRUE(rules.count("profile-max-pdos")) << describe(found);
    EXPECT_TRUE(rules.count("profile-pdo-index-range")) << describe(found);
    // The finding points at the YAML line of the fifth PDO.
    for (const auto& d : found) {
        if (d.rule != "profile-pdo-index-range") continue;
        EXPECT_NE(s.source->line(d.pos.line).find("0x1604"), std::string_view::npos) << d.pos.line;
    }
}
