// The reader reads a document a device at a time: the parser builds the elements of one Device
// (or Module, or the Vendor, Groups, ...) and drops them once they are in the model (issue 25). That
// must not change what is read: the model (as written back), its positions and the reader's and
// the rules' diagnostics are those of reading each device from a document of its own, with the
// positions moved by where that device stands in the catalogue.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "esi/check/run.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "support/test_support.hpp"

namespace {

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

// The catalogue read as a whole and each device read from a document of its own, with the same
// lines before it (so that positions agree): the same device, positions and findings.
TEST(ReaderStreaming, EachDeviceReadsAsIfItStoodAlone) {
    const std::string xml = big_catalogue();
    const esi::ReadResult whole = esi::read_esi(xml, "big.xml");
    ASSERT_TRUE(whole.document);
    const auto& info = whole.document->infos.at(0);
    ASSERT_EQ(info.devices.size(), 8u);
    EXPECT_EQ(info.devices[7].profiles.at(0).dictionary->objects.size(), 300u);
    EXPECT_EQ(info.devices[7].profiles.at(0).dictionary->objects[299].names.at(0).text, "Object & name 299");
    ASSERT_EQ(info.modules.size(), 2u);
    ASSERT_EQ(info.descriptions_extras.elements.size(), 1u);
    EXPECT_EQ(info.descriptions_extras.elements[0].after, "Modules");

    std::size_t from = 0;
    for (std::size_t d = 0; d < info.devices.size(); ++d) {
        SCOPED_TRACE("device " + std::to_string(d));
        from = xml.find("<Device ", from);
        const std::size_t to = xml.find("</Device>", from) + 9;
        // Everything before the device blanked to spaces (line feeds kept): the device keeps its line:column.
        std::string alone = xml.substr(0, from);
        for (char& c : alone)
            if (c != '\n') c = ' ';
        const std::string open = "<EtherCATInfo><Descriptions><Devices>";
        const std::size_t room = alone.find(std::string(open.size(), ' '));
        ASSERT_NE(room, std::string::npos);
        alone.replace(room, open.size(), open);
        alone += xml.substr(from, to - from) + "</Devices></Descriptions></EtherCATInfo>";
        const esi::ReadResult single = esi::read_esi(alone, "big.xml");
        ASSERT_TRUE(single.document);
        const esi::Device& device = single.document->infos.at(0).devices.at(0);
        EXPECT_EQ(device.pos, info.devices[d].pos);
        esi::EsiDocument one;
        one.infos.emplace_back().devices.push_back(info.devices[d]);
        esi::EsiDocument other;
        other.infos.emplace_back().devices.push_back(device);
        EXPECT_EQ(esi::write_esi(one), esi::write_esi(other));
        EXPECT_EQ(positions(one), positions(other));
        from = to;
    }
}

// The parser drops a device's elements once it is read: a deeply nested device is taken apart
// without recursion, and the device after it is read.
TEST(ReaderStreaming, ReadsADeeplyNestedDeviceWithoutOverflowingTheStack) {
    const int depth = 1'000'000;
    std::string xml = "<?xml version=\"1.0\"?>\n<EtherCATInfo><Vendor><Id>1</Id><Name>V</Name></Vendor><Descriptions><Devices>"
                      "<Device><Type ProductCode=\"1\" RevisionNo=\"1\">D</Type><Name>D</Name><Deep>";
    for (int i = 0; i < depth; ++i) xml += "<a>";
    for (int i = 0; i < depth; ++i) xml += "</a>";
    xml += "</Deep></Device><Device><Type ProductCode=\"2\" RevisionNo=\"1\">E</Type><Name>E</Name></Device>"
           "</Devices></Descriptions></EtherCATInfo>\n";
    const esi::ReadResult read = esi::read_esi(xml, "deep.xml");
    ASSERT_TRUE(read.document);
    ASSERT_EQ(read.document->infos.at(0).devices.size(), 2u);
    EXPECT_EQ(read.document->infos.at(0).devices[1].names.at(0).text, "E");
}

// A fault after a device that was read already: no document, the xml-syntax error alone (what the
// reader found in the devices before it is dropped).
TEST(ReaderStreaming, AFaultAfterTheFirstDevicesLeavesTheSyntaxErrorAlone) {
    std::string xml = big_catalogue();
    const std::size_t last = xml.rfind("</Devices>");
    xml.insert(last, "<Device><Type ProductCode=\"0x5\">X</Type></Devce>");
    const esi::ReadResult read = esi::read_esi(xml, "big.xml");
    EXPECT_FALSE(read.document);
    ASSERT_EQ(read.diagnostics.size(), 1u) << diagnostics(read.diagnostics);
    EXPECT_EQ(read.diagnostics.items()[0].rule, "xml-syntax");
    EXPECT_NE(read.diagnostics.items()[0].message.find("end tag 'Devce' does not match the start tag 'Device'"), std::string::npos)
        << read.diagnostics.items()[0].message;
}

}  // namespace
