// Vendor, Groups and the EtherCATInfo root: element order, number formats, localized names.

#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;
using esi::test::rewrite;

const std::string vendor_file = R"(<?xml version="1.0" encoding="ISO-8859-1"?>
<EtherCATInfo xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" Version="1.6" xsi:noNamespaceSchemaLocation="EtherCATInfo.xsd">
  <Vendor FileVersion="7" UniqueName="acme">
    <Id>2</Id>
    <Name LcId="1033">Acme</Name>
    <Name LcId="1031">Acme GmbH</Name>
    <Comment>c</Comment>
    <URL LcId="1033">https://example.com/?a=1&amp;b=2</URL>
    <DescriptionURL>https://example.com/esi</DescriptionURL>
    <ImageData16x14>0a0B</ImageData16x14>
  </Vendor>
  <Descriptions>
    <Groups>
      <Group SortOrder="3" ParentGroup="Root">
        <Type>DIO</Type>
        <Name LcId="1033">Digital I/O</Name>
        <Comment>all digital</Comment>
        <ImageFile16x14>dio.bmp</ImageFile16x14>
      </Group>
      <Group><Type>AIO</Type><Name>Analog</Name></Group>
    </Groups>
    <Devices/>
  </Descriptions>
</EtherCATInfo>
)";

TEST(WriterVendor, WritesVendorInSchemaOrderWithIdAsEightHexDigits) {
    const std::string out = rewrite(vendor_file);
    EXPECT_TRUE(contains(out,
                         "  <Vendor UniqueName=\"acme\" FileVersion=\"7\">\n"
                         "    <Id>#x00000002</Id>\n"
                         "    <Name LcId=\"1033\">Acme</Name>\n"
                         "    <Name LcId=\"1031\">Acme GmbH</Name>\n"
                         "    <Comment>c</Comment>\n"
                         "    <URL LcId=\"1033\">https://example.com/?a=1&amp;b=2</URL>\n"
                         "    <DescriptionURL>https://example.com/esi</DescriptionURL>\n"
                         "    <ImageData16x14>0A0B</ImageData16x14>\n"
                         "  </Vendor>\n"))
        << out;
}

TEST(WriterVendor, WritesRootVersionThenNamespaceAttributes) {
    const std::string out = rewrite(vendor_file);
    EXPECT_EQ(out.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATInfo Version=\"1.6\" "
                        "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
                        "xsi:noNamespaceSchemaLocation=\"EtherCATInfo.xsd\">\n",
                        0),
              0u)
        << out;
}

TEST(WriterVendor, WritesGroupsWithAttributesAndImages) {
    const std::string out = rewrite(vendor_file);
    EXPECT_TRUE(contains(out,
                         "      <Group SortOrder=\"3\" ParentGroup=\"Root\">\n"
                         "        <Type>DIO</Type>\n"
                         "        <Name LcId=\"1033\">Digital I/O</Name>\n"
                         "        <Comment>all digital</Comment>\n"
                         "        <ImageFile16x14>dio.bmp</ImageFile16x14>\n"
                         "      </Group>\n"
                         "      <Group>\n"
                         "        <Type>AIO</Type>\n"
                         "        <Name>Analog</Name>\n"
                         "      </Group>\n"))
        << out;
}

TEST(WriterVendor, EmptyDevicesAndGroupsStayPresent) {
    const std::string out = rewrite(vendor_file);
    EXPECT_TRUE(contains(out, "    <Devices/>\n")) << out;
    EXPECT_EQ(esi::test::tree_differences(vendor_file), "");
}

TEST(WriterVendor, GroupsAndDevicesAreWrittenEvenWhenTheModelHasNone) {
    // Both are required by the schema; a hand-built model without them still gets them.
    esi::EsiDocument doc;
    doc.kind = esi::DocumentKind::ethercat_info;
    doc.infos.emplace_back();
    doc.infos[0].vendor = esi::Vendor{};
    doc.infos[0].vendor->id = 0x0E4A;
    doc.infos[0].vendor->names.push_back({"Example", std::nullopt, {}});
    doc.infos[0].has_descriptions = true;
    const std::string out = esi::write_esi(doc);
    EXPECT_TRUE(contains(out, "  <Descriptions>\n    <Groups/>\n    <Devices/>\n  </Descriptions>\n")) << out;
}

TEST(WriterVendor, NamesKeepTheirLanguageAndText) {
    const auto doc = esi::test::read_ok(rewrite(vendor_file));
    const auto& names = doc.infos.at(0).vendor->names;
    ASSERT_EQ(names.size(), 2u);
    EXPECT_EQ(names[1].lcid, 1031u);
    EXPECT_EQ(names[1].text, "Acme GmbH");
    EXPECT_EQ(doc.infos[0].vendor->urls.at(0).text, "https://example.com/?a=1&b=2");
}

TEST(WriterVendor, NonAsciiTextFromALatin1FileComesOutAsUtf8) {
    const std::string latin1 = "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n<EtherCATInfo><Vendor><Id>1</Id>"
                               "<Name>M\xFC" "ller</Name></Vendor><Descriptions><Groups/><Devices/></Descriptions></EtherCATInfo>";
    const std::string out = rewrite(latin1);
    EXPECT_TRUE(contains(out, "<Name>M\xC3\xBCller</Name>")) << out;
    EXPECT_TRUE(contains(out, "encoding=\"UTF-8\""));
}

}  // namespace
