// The reader frees each Device, Module, Object and DataType of the parsed XML, and its part of
// the parse buffer, once it is in the model (ReadOptions::release_elements_from_bytes, issue 10).
// That must not change what is read: the model (as written back), its positions and the reader's
// and the rules' diagnostics are the same with and without releasing.

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "esi/check/run.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "support/test_support.hpp"
#include "xml/parse_buffer.hpp"

namespace {

using esi::ReadOptions;

ReadOptions releasing(bool on) {
    ReadOptions options;
    options.release_elements_from_bytes = on ? 0 : std::numeric_limits<std::size_t>::max();
    return options;
}

std::string where(esi::SourcePos pos) { return std::to_string(pos.line) + ":" + std::to_string(pos.column); }

void dictionary_positions(const esi::Dictionary& d, std::string& out) {
    out += " dictionary " + where(d.pos);
    for (const auto& t : d.data_types) {
        out += " type " + where(t.pos);
        for (const auto& s : t.sub_items) out += " " + where(s.pos);
    }
    for (const auto& o : d.objects) {
        out += " object " + where(o.pos);
        if (o.info)
            for (const auto& s : o.info->sub_items) out += " " + where(s.pos);
    }
    for (const auto& e : d.extras.elements) out += " extra " + e.name + "@" + where(e.pos) + " after " + e.after;
}

// The positions of what is released and of what follows it.
std::string positions(const esi::EsiDocument& doc) {
    std::string out;
    for (const auto& info : doc.infos) {
        for (const auto& device : info.devices) {
            out += "\ndevice " + where(device.pos);
            for (const auto& p : device.profiles)
                if (p.dictionary) dictionary_positions(*p.dictionary, out);
        }
        for (const auto& module : info.modules) {
            out += "\nmodule " + where(module.pos);
            if (module.profile && module.profile->dictionary) dictionary_positions(*module.profile->dictionary, out);
        }
        for (const auto& e : info.descriptions_extras.elements) out += "\nextra " + e.name + "@" + where(e.pos) + " after " + e.after;
    }
    if (doc.dictionary) dictionary_positions(*doc.dictionary, out);
    return out;
}

std::string diagnostics(const esi::Diagnostics& found) {
    std::string out;
    for (const auto& d : found) out += esi::format_diagnostic_line(d);
    return out;
}

// Reads `xml` both ways and expects the same model, positions and diagnostics.
void expect_same_either_way(const std::string& xml, const std::string& path) {
    const esi::ReadResult kept = esi::read_esi(xml, path, releasing(false));
    const esi::ReadResult released = esi::read_esi(xml, path, releasing(true));
    EXPECT_EQ(diagnostics(kept.diagnostics), diagnostics(released.diagnostics)) << path;
    ASSERT_EQ(kept.document.has_value(), released.document.has_value()) << path;
    if (!kept.document) return;
    EXPECT_EQ(esi::write_esi(*kept.document), esi::write_esi(*released.document)) << path;
    EXPECT_EQ(positions(*kept.document), positions(*released.document)) << path;
    EXPECT_EQ(diagnostics(esi::run_rules(*kept.document, esi::EffectiveConfig{})),
              diagnostics(esi::run_rules(*released.document, esi::EffectiveConfig{})))
        << path;
}

// Devices and Objects of several pages each, with character data between them and unknown
// elements after them, so that pages are given back right before what is still read.
std::string big_catalogue() {
    std::string objects;
    for (int i = 0; i < 300; ++i) {
        objects += "<Object><Index>#x" + std::to_string(2000 + i) +
                   "</Index><Name>Object &amp; name " + std::to_string(i) +
                   "</Name><Type>UDINT</Type><BitSize>32</BitSize><Info><DefaultValue>" + std::to_string(i) +
                   "</DefaultValue></Info><Flags><Access>rw</Access></Flags></Object>\n";
    }
    std::string devices;
    for (int d = 0; d < 8; ++d) {
        devices += "<Device Physics=\"YY\"><Type ProductCode=\"#x" + std::to_string(100 + d) +
                   "\" RevisionNo=\"1\">Dev</Type><Name>Device " + std::to_string(d) +
                   "</Name><Profile><ProfileNo>5001</ProfileNo><Dictionary><DataTypes>"
                   "<DataType><Name>UDINT</Name><BitSize>32</BitSize></DataType></DataTypes><Objects>\n" +
                   objects + "</Objects><Unknown a=\"1\">after the objects</Unknown></Dictionary></Profile></Device>\n";
        if (d == 1) devices += "stray text between devices\n";
    }
    return "<?xml version=\"1.0\"?>\n<EtherCATInfo><Vendor><Id>2</Id><Name>V</Name></Vendor><Descriptions>"
           "<Groups><Group><Type>G</Type><Name>G</Name></Group></Groups><Devices>\n" +
           devices + "</Devices><Modules><Module><Type ModuleIdent=\"1\">M</Type><Name>M</Name></Module>"
           "<Module><Type ModuleIdent=\"2\">N</Type><Name>N</Name></Module></Modules>"
           "<VendorSpecific><Kept>text</Kept></VendorSpecific></Descriptions></EtherCATInfo>\n";
}

TEST(ReaderRelease, ReadsBigDevicesTheSameAsWithoutReleasing) {
    const std::string xml = big_catalogue();
    ASSERT_GT(xml.size(), 4u * 64 * 1024);  // many pages, whatever the page size
    expect_same_either_way(xml, "big.xml");
    const esi::ReadResult released = esi::read_esi(xml, "big.xml", releasing(true));
    ASSERT_TRUE(released.document);
    const auto& info = released.document->infos.at(0);
    ASSERT_EQ(info.devices.size(), 8u);
    EXPECT_EQ(info.devices[7].profiles.at(0).dictionary->objects.size(), 300u);
    EXPECT_EQ(info.devices[7].profiles.at(0).dictionary->objects[299].names.at(0).text, "Object & name 299");
    ASSERT_EQ(info.modules.size(), 2u);
    ASSERT_EQ(info.descriptions_extras.elements.size(), 1u);
    EXPECT_EQ(info.descriptions_extras.elements[0].after, "Modules");
}

// pugixml frees a subtree recursively; a Device nesting elements a million deep must not
// overflow the stack when it is released.
TEST(ReaderRelease, ReleasesADeeplyNestedDeviceWithoutOverflowingTheStack) {
    const int depth = 1'000'000;
    std::string xml = "<?xml version=\"1.0\"?>\n<EtherCATInfo><Vendor><Id>1</Id><Name>V</Name></Vendor><Descriptions><Devices>"
                      "<Device><Type ProductCode=\"1\" RevisionNo=\"1\">D</Type><Name>D</Name><Deep>";
    for (int i = 0; i < depth; ++i) xml += "<a>";
    for (int i = 0; i < depth; ++i) xml += "</a>";
    xml += "</Deep></Device><Device><Type ProductCode=\"2\" RevisionNo=\"1\">E</Type><Name>E</Name></Device>"
           "</Devices></Descriptions></EtherCATInfo>\n";
    const esi::ReadResult released = esi::read_esi(xml, "deep.xml", releasing(true));
    ASSERT_TRUE(released.document);
    ASSERT_EQ(released.document->infos.at(0).devices.size(), 2u);
    EXPECT_EQ(released.document->infos.at(0).devices[1].names.at(0).text, "E");
}

TEST(ReaderRelease, ReadsTheCorpusTheSameAsWithoutReleasing) {
    ESI_REQUIRE_CORPUS();
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(esi::test::corpus_esi_dir())) {
        if (entry.path().extension() != ".xml") continue;
        expect_same_either_way(esi::test::read_text(entry.path()), entry.path().filename().string());
        ++files;
    }
    EXPECT_GT(files, 50u);
}

TEST(ParseBuffer, GivesBackWholePagesInsideTheRangeOnly) {
    const std::size_t size = 1 << 20;
    const std::string text(size, 'x');
    esi::xml_reader::ParseBuffer buffer(text, true);
    ASSERT_EQ(buffer.view(), text);
    buffer.give_back(100, size - 100);
    // Bytes next to the range's ends, which are never on a page wholly inside it, are kept.
    EXPECT_EQ(buffer.view().substr(0, 100), text.substr(0, 100));
    EXPECT_EQ(buffer.view().substr(size - 100), text.substr(size - 100));
#if defined(__linux__)
    EXPECT_EQ(buffer.view()[size / 2], '\0');  // given back: reads as zero
#endif
    esi::xml_reader::ParseBuffer on_heap(text, false);
    on_heap.give_back(0, size);
    EXPECT_EQ(on_heap.view(), text);
}

}  // namespace
