// The four ESI roots, and the root chosen for a model whose kind was not set.

#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;
using esi::test::rewrite;

TEST(WriterRoots, WritesAnInfoListWithEachInfoAndItsExtras) {
    const std::string list = R"(<?xml version="1.0"?>
<EtherCATInfoList Tool="igh">
  <Comment>written by a tool</Comment>
  <EtherCATInfo>
    <Vendor><Id>2</Id></Vendor>
    <Descriptions><Devices><Device><Type ProductCode="#x1" RevisionNo="#x2">A</Type><Name>A</Name><Sm>x</Sm></Device></Devices></Descriptions>
  </EtherCATInfo>
  <EtherCATInfo>
    <Vendor><Id>3</Id></Vendor>
    <Descriptions><Devices/></Descriptions>
  </EtherCATInfo>
</EtherCATInfoList>
)";
    const std::string out = rewrite(list);
    EXPECT_EQ(out.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATInfoList Tool=\"igh\">\n  <Comment>written by a tool</Comment>\n"
                        "  <EtherCATInfo>\n    <Vendor>\n      <Id>#x00000002</Id>\n",
                        0),
              0u)
        << out;
    EXPECT_TRUE(contains(out, "  </EtherCATInfo>\n  <EtherCATInfo>\n    <Vendor>\n      <Id>#x00000003</Id>\n")) << out;
    const auto doc = esi::test::read_ok(out);
    EXPECT_EQ(doc.kind, esi::DocumentKind::ethercat_info_list);
    ASSERT_EQ(doc.infos.size(), 2u);
    EXPECT_EQ(doc.infos[0].devices.at(0).type.product_code, 1u);
}

TEST(WriterRoots, WritesADictionaryFile) {
    const std::string dict = R"(<?xml version="1.0" encoding="utf-8"?>
<EtherCATDict xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="..\EtherCATDict.xsd" Version="2">
  <Dictionary>
    <DataTypes><DataType><Name>UINT</Name><BitSize>16</BitSize></DataType></DataTypes>
    <Objects><Object><Index>#x1000</Index><Name>Device type</Name><Type>UINT</Type><BitSize>16</BitSize></Object></Objects>
  </Dictionary>
</EtherCATDict>
)";
    const std::string out = rewrite(dict);
    EXPECT_EQ(out.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATDict Version=\"2\" "
                        "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xsi:noNamespaceSchemaLocation=\"..\\EtherCATDict.xsd\">\n"
                        "  <Dictionary>\n    <DataTypes>\n",
                        0),
              0u)
        << out;
    EXPECT_EQ(esi::test::tree_differences(dict), "");
}

TEST(WriterRoots, AModelWithoutKindAndOnlyADictionaryIsADictionaryFile) {
    esi::EsiDocument doc;
    doc.dictionary = esi::Dictionary{};
    const std::string out = esi::write_esi(doc);
    EXPECT_EQ(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATDict>\n  <Dictionary>\n    <Objects/>\n  </Dictionary>\n</EtherCATDict>\n");
}

TEST(WriterRoots, AModelWithoutKindAndOneInfoIsAnEtherCATInfo) {
    esi::EsiDocument doc;
    doc.infos.emplace_back();
    doc.infos[0].version = "1.17";
    EXPECT_EQ(esi::write_esi(doc), "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATInfo Version=\"1.17\"/>\n");
}

TEST(WriterRoots, SeveralInfosAreNeverSilentlyDropped) {
    esi::EsiDocument doc;
    doc.kind = esi::DocumentKind::ethercat_info;  // inconsistent: only a list holds several infos
    doc.infos.resize(2);
    doc.infos[1].version = "second";
    const std::string out = esi::write_esi(doc);
    EXPECT_TRUE(contains(out, "<EtherCATInfoList>\n  <EtherCATInfo/>\n  <EtherCATInfo Version=\"second\"/>\n</EtherCATInfoList>\n")) << out;
}

TEST(WriterRoots, AnEmptyDocumentIsStillWellFormed) {
    EXPECT_EQ(esi::write_esi(esi::EsiDocument{}), "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATInfo/>\n");
}

}  // namespace
