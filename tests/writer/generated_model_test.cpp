// A model built in code, as esi-gen builds one from YAML: the writer's output is deterministic,
// round-trips through the reader, and is valid against schema 1.17 when the model has the
// required fields (including a DataType for every type an Object or SubItem names).

#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;

esi::LocalizedText text(std::string s, std::optional<std::uint32_t> lcid = std::nullopt) { return {std::move(s), lcid, {}}; }

esi::DataType basic_type(std::string name, std::uint64_t bits) {
    esi::DataType t;
    t.name = std::move(name);
    t.bit_size = bits;
    return t;
}

esi::ObjectFlags flags(std::string access, std::optional<std::string> pdo_mapping = std::nullopt) {
    esi::ObjectFlags f;
    f.access = std::move(access);
    f.pdo_mapping = std::move(pdo_mapping);
    return f;
}

// The small digital I/O device of the esi-gen samples, built field by field.
esi::EsiDocument generated_device() {
    esi::EsiDocument doc;
    doc.kind = esi::DocumentKind::ethercat_info;
    esi::EtherCATInfo& info = doc.infos.emplace_back();
    info.version = "1.17";
    info.vendor.emplace();
    info.vendor->id = 0x0E4A;
    info.vendor->names = {text("Example Automation")};
    info.has_descriptions = true;
    esi::Group& group = info.groups.emplace_back();
    group.type = "DigIO";
    group.names = {text("Digital I/O", 1033)};

    esi::Device& d = info.devices.emplace_back();
    d.physics = "YY";
    d.type.text = "DIO-8";
    d.type.product_code = 0x00010001;
    d.type.revision_no = 0x00010000;
    d.names = {text("DIO-8 8 in / 8 out", 1033), text("DIO-8 8 Ein / 8 Aus", 1031)};
    d.group_type = "DigIO";

    esi::Profile& profile = d.profiles.emplace_back();
    esi::Dictionary& dict = profile.dictionary.emplace();
    dict.data_types = {basic_type("UDINT", 32), basic_type("USINT", 8), basic_type("BOOL", 1), basic_type("STRING(5)", 40)};
    esi::DataType identity = basic_type("DT1018", 144);
    const std::pair<const char*, const char*> subs[] = {{"SubIndex 000", "USINT"}, {"Vendor ID", "UDINT"}, {"Product code", "UDINT"},
                                                        {"Revision", "UDINT"},     {"Serial number", "UDINT"}};
    std::uint64_t offset = 0;
    for (std::uint32_t i = 0; i < 5; ++i) {
        esi::DataTypeSubItem s;
        s.subindex = i;
        s.name = subs[i].first;
        s.type = subs[i].second;
        s.bit_size = i == 0 ? 8 : 32;
        s.bit_offset = offset;
        offset += i == 0 ? 16 : 32;
        s.flags = flags("ro");
        identity.sub_items.push_back(s);
    }
    dict.data_types.push_back(identity);

    esi::Object device_name;
    device_name.index = 0x1008;
    device_name.names = {text("Device name")};
    device_name.type = "STRING(5)";
    device_name.bit_size = 40;
    device_name.info.emplace().default_string = "DIO-8";
    device_name.flags = flags("ro");
    dict.objects.push_back(device_name);

    esi::Object id;
    id.index = 0x1018;
    id.names = {text("Identity")};
    id.type = "DT1018";
    id.bit_size = 144;
    esi::ObjectInfo& id_info = id.info.emplace();
    const std::uint64_t values[] = {4, 0x0E4A, 0x00010001, 0x00010000, 0};
    for (std::size_t i = 0; i < 5; ++i) {
        esi::ObjectSubItemInfo s;
        s.name = subs[i].first;
        s.info.default_value = esi::Number::from_unsigned(values[i]);
        id_info.sub_items.push_back(s);
    }
    id.flags = flags("ro");
    dict.objects.push_back(id);

    esi::Object input;
    input.index = 0x6000;
    input.names = {text("Input 1")};
    input.type = "BOOL";
    input.bit_size = 1;
    input.flags = flags("ro", "T");
    dict.objects.push_back(input);

    for (const char* type : {"Outputs", "Inputs"}) d.fmmus.emplace_back().type = type;
    esi::SyncManager out_sm;
    out_sm.type = "Outputs";
    out_sm.start_address = 0x0F00;
    out_sm.control_byte = 0x44;
    out_sm.default_size = 1;
    out_sm.enable = 1;
    esi::SyncManager in_sm = out_sm;
    in_sm.type = "Inputs";
    in_sm.start_address = 0x1000;
    in_sm.control_byte = 0x00;
    d.sms = {out_sm, in_sm};

    esi::Pdo tx;
    tx.direction = esi::PdoDirection::tx;
    tx.index = 0x1A00;
    tx.fixed = true;
    tx.sm = 1;
    tx.names = {text("Inputs")};
    esi::PdoEntry e;
    e.index = 0x6000;
    e.subindex = 1;
    e.bit_len = 1;
    e.names = {text("Input 1")};
    e.data_type = "BOOL";
    tx.entries.push_back(e);
    esi::PdoEntry pad;
    pad.bit_len = 7;
    tx.entries.push_back(pad);
    d.tx_pdos.push_back(tx);

    esi::Dc& dc = d.dc.emplace();
    esi::DcOpMode& free_run = dc.op_modes.emplace_back();
    free_run.name = "FreeRun";
    free_run.desc = "Free run";
    free_run.has_assign_activate = true;
    esi::DcOpMode& sync = dc.op_modes.emplace_back();
    sync.name = "DcSync";
    sync.assign_activate = 0x300;
    sync.cycle_time_sync0.emplace().factor = 1;
    sync.shift_time_sync0.emplace().value = 0;

    esi::Eeprom& eeprom = d.eeprom.emplace();
    eeprom.byte_size = 2048;
    eeprom.config_data = esi::HexData{"8003006EFF00FF000000", {}};
    return doc;
}

TEST(WriterGenerated, OutputIsByteIdenticalOnEveryRun) {
    const auto doc = generated_device();
    const std::string first = esi::write_esi(doc);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(esi::write_esi(doc), first);
    EXPECT_EQ(esi::write_esi(generated_device()), first);
    EXPECT_EQ(first.back(), '\n');
    EXPECT_FALSE(contains(first, "\r"));
}

TEST(WriterGenerated, ReadingTheOutputGivesTheModelBack) {
    const auto doc = generated_device();
    const auto back = esi::test::read_ok(esi::write_esi(doc));
    const auto result = esi::read_esi(esi::write_esi(doc), "gen.xml");
    EXPECT_TRUE(result.diagnostics.empty()) << result.diagnostics.items()[0].message;
    const auto& d = back.infos.at(0).devices.at(0);
    EXPECT_EQ(back.infos[0].vendor->id, 0x0E4Au);
    EXPECT_EQ(d.type.product_code, 0x00010001u);
    EXPECT_EQ(d.names.at(1).lcid, 1031u);
    EXPECT_EQ(d.sms.at(1).start_address, 0x1000u);
    EXPECT_EQ(d.sms.at(1).control_byte, 0u);
    EXPECT_EQ(d.tx_pdos.at(0).bit_size(), 8u);
    EXPECT_EQ(d.dc->op_modes.at(0).has_assign_activate, true);
    EXPECT_EQ(d.dc->op_modes.at(0).assign_activate, 0u);
    EXPECT_EQ(d.dc->op_modes.at(1).assign_activate, 0x300u);
    EXPECT_EQ(d.dictionary()->objects.at(1).info->sub_items.at(1).info.default_value, esi::Number::from_unsigned(0x0E4A));
    EXPECT_EQ(esi::write_esi(back), esi::write_esi(doc));
}

TEST(WriterGenerated, OutputIsValidAgainstSchema117) {
    ESI_REQUIRE_CORPUS();
    ASSERT_NE(esi::test::schema_1_17(), nullptr);
    EXPECT_EQ(esi::test::schema_errors(esi::write_esi(generated_device())), "");
}

TEST(WriterGenerated, SchemaWantsEveryObjectTypeDeclared) {
    // The writer does not invent DataTypes: a generator has to declare them (docs/esi-writer.md).
    ESI_REQUIRE_CORPUS();
    auto doc = generated_device();
    auto& types = doc.infos[0].devices[0].profiles[0].dictionary->data_types;
    types.erase(types.begin() + 2);  // BOOL, used by object 0x6000
    EXPECT_TRUE(contains(esi::test::schema_errors(esi::write_esi(doc)), "BOOL")) << esi::test::schema_errors(esi::write_esi(doc));
}

TEST(WriterGenerated, OptionsChangeLayoutOnly) {
    const auto doc = generated_device();
    esi::WriteOptions options;
    options.indent = "\t";
    options.line_ending = "\r\n";
    const std::string crlf = esi::write_esi(doc, options);
    EXPECT_TRUE(contains(crlf, "\r\n\t<Vendor>\r\n\t\t<Id>#x00000E4A</Id>\r\n"));
    const auto result = esi::test::compare_xml_trees(esi::write_esi(doc), crlf);
    ASSERT_TRUE(result.parsed);
    EXPECT_TRUE(result.differences.empty());
}

TEST(WriterGenerated, WriteFileReplacesTheTargetAtomically) {
    esi::test::TempDir dir;
    const auto path = dir / "out" / "device.xml";
    const auto doc = generated_device();
    EXPECT_TRUE(esi::write_esi_file(path, doc).empty());
    EXPECT_EQ(esi::test::read_text(path), esi::write_esi(doc));
    // A target that cannot be written (a directory in its place) is an io-error, not a throw.
    std::filesystem::create_directories(dir / "blocked.xml");
    const auto diagnostics = esi::write_esi_file(dir / "blocked.xml", doc);
    ASSERT_FALSE(diagnostics.empty());
    EXPECT_EQ(diagnostics.items()[0].rule, "io-error");
    EXPECT_TRUE(std::filesystem::is_directory(dir / "blocked.xml"));
}

}  // namespace
