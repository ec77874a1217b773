// Slots of a modular device and the Modules they take (in EtherCATInfo and EtherCATModule roots).

#include "writer/writer_test_support.hpp"

namespace {

using esi::test::contains;
using esi::test::rewrite;

const std::string modular_file = R"(<?xml version="1.0"?>
<EtherCATInfo Version="1.17">
  <Vendor><Id>#x4711</Id><Name>Example</Name></Vendor>
  <Descriptions>
    <Groups><Group><Type>Coupler</Type><Name>Coupler</Name></Group></Groups>
    <Devices>
      <Device Physics="YY">
        <Type ProductCode="#x100" RevisionNo="1">Coupler</Type>
        <Name>Coupler</Name>
        <GroupType>Coupler</GroupType>
        <Slots MaxSlotCount="254" MaxSlotGroupCount="1" SlotPdoIncrement="1" SlotGroupPdoIncrement="0" SlotIndexIncrement="#x10"
               SlotGroupIndexIncrement="0" DownloadModuleIdentList="true">
          <Slot SlotGroup="0" MinInstances="0" MaxInstances="#xFE" SlotPdoIncrement="2" SlotGroupPdoIncrement="3" SlotIndexIncrement="16"
                SlotGroupIndexIncrement="4" Default="#x1001" Fallback="#x1000" TreeView="SLOT">
            <Name>Slot 1</Name>
            <ModuleIdent Default="1">#x00001001</ModuleIdent>
            <ModuleIdent>4098</ModuleIdent>
            <ImageData16x14>aa</ImageData16x14>
          </Slot>
          <Slot MinInstances="1" MaxInstances="1">
            <ModuleClass><Class>DIO</Class><VendorId>#x4711</VendorId><Name>Digital</Name><ImageFile16x14>a.bmp</ImageFile16x14></ModuleClass>
          </Slot>
          <SlotGroupData SlotGroup="0"><Name>G</Name></SlotGroupData>
        </Slots>
      </Device>
    </Devices>
    <Modules>
      <Module Crc32="#x1">
        <Type ModuleIdent="#x1001" ModuleClass="DIO" ModulePdoGroup="1" SRA_ParameterSupported="0">DI8</Type>
        <Name>8 inputs</Name>
        <RxPdo><Index DependOnSlot="1">#x1600</Index><Name>o</Name></RxPdo>
        <TxPdo Sm="3"><Index DependOnSlot="1">#x1A00</Index><Name>i</Name>
          <Entry><Index DependOnSlot="1">#x6000</Index><SubIndex>1</SubIndex><BitLen>1</BitLen><DataType>BOOL</DataType></Entry></TxPdo>
        <SafetyParaMapping><Index>#x1700</Index><Name>s</Name></SafetyParaMapping>
        <Mailbox><CoE ModuleOD="1"><InitCmd><Transition>PS</Transition><Index DependOnSlot="1">#x8000</Index><SubIndex>1</SubIndex><Data>01</Data></InitCmd></CoE></Mailbox>
        <Profile><ProfileNo>5001</ProfileNo><Dictionary><Objects><Object><Index DependOnSlot="1">#x6000</Index><Name>in</Name><Type>BOOL</Type><BitSize>1</BitSize></Object></Objects></Dictionary></Profile>
        <DcOpModeName>DcSync</DcOpModeName>
        <ImageData16x14>bb</ImageData16x14>
      </Module>
    </Modules>
  </Descriptions>
</EtherCATInfo>
)";

TEST(WriterSlots, WritesSlotsAttributesAndModuleIdents) {
    const std::string out = rewrite(modular_file);
    EXPECT_TRUE(contains(out,
                         R"(<Slots MaxSlotCount="254" MaxSlotGroupCount="1" SlotPdoIncrement="1" SlotGroupPdoIncrement="0" SlotIndexIncrement="16" )"
                         R"(SlotGroupIndexIncrement="0" DownloadModuleIdentList="true">)"))
        << out;
    EXPECT_TRUE(contains(out,
                         "          <Slot SlotGroup=\"0\" MinInstances=\"0\" MaxInstances=\"254\" SlotPdoIncrement=\"2\" SlotGroupPdoIncrement=\"3\" "
                         "SlotIndexIncrement=\"16\" SlotGroupIndexIncrement=\"4\" Default=\"#x00001001\" Fallback=\"#x00001000\" TreeView=\"SLOT\">\n"
                         "            <Name>Slot 1</Name>\n"
                         "            <ModuleIdent Default=\"1\">#x00001001</ModuleIdent>\n"
                         "            <ModuleIdent>#x00001002</ModuleIdent>\n"
                         "            <ImageData16x14>AA</ImageData16x14>\n"
                         "          </Slot>\n"))
        << out;
}

TEST(WriterSlots, WritesModuleClassesAndKeepsSlotGroupData) {
    const std::string out = rewrite(modular_file);
    EXPECT_TRUE(contains(out,
                         "            <ModuleClass>\n"
                         "              <Class>DIO</Class>\n"
                         "              <VendorId>#x00004711</VendorId>\n"
                         "              <Name>Digital</Name>\n"
                         "              <ImageFile16x14>a.bmp</ImageFile16x14>\n"
                         "            </ModuleClass>\n"))
        << out;
    EXPECT_TRUE(contains(out, "          </Slot>\n          <SlotGroupData SlotGroup=\"0\">\n")) << out;
}

TEST(WriterModules, WritesModulesInSchemaOrder) {
    const std::string out = rewrite(modular_file);
    EXPECT_TRUE(contains(out, "      <Module Crc32=\"#x1\">\n"
                              "        <Type ModuleIdent=\"#x00001001\" ModuleClass=\"DIO\" ModulePdoGroup=\"1\" SRA_ParameterSupported=\"0\">DI8</Type>\n"
                              "        <Name>8 inputs</Name>\n"
                              "        <RxPdo>\n"))
        << out;
    const char* order[] = {"<TxPdo Sm=\"3\">", "<SafetyParaMapping>", "<Mailbox>", "<CoE ModuleOD=\"true\">", "<Profile>",
                           "<DcOpModeName>DcSync</DcOpModeName>", "<ImageData16x14>BB</ImageData16x14>", "</Module>"};
    std::size_t last = out.find("<Module ");
    for (const char* tag : order) {
        const std::size_t at = out.find(tag, last);
        ASSERT_NE(at, std::string::npos) << tag << " missing or out of order in\n" << out;
        last = at;
    }
    EXPECT_TRUE(contains(out, "<Index DependOnSlot=\"true\">#x6000</Index>\n                <Name>in</Name>")) << out;
}

TEST(WriterModules, RoundTripLosesNothing) { EXPECT_EQ(esi::test::tree_differences(modular_file), ""); }

TEST(WriterModules, ModuleRootHasVendorThenModules) {
    const std::string module_file = R"(<?xml version="1.0"?>
<EtherCATModule Version="1.3" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
  <Vendor><Id>2</Id><Name>B</Name></Vendor>
  <Modules>
    <Module><Type ModuleIdent="#x10">M</Type><Name>M</Name></Module>
  </Modules>
</EtherCATModule>
)";
    const std::string out = rewrite(module_file);
    EXPECT_EQ(out,
              "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<EtherCATModule Version=\"1.3\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n"
              "  <Vendor>\n"
              "    <Id>#x00000002</Id>\n"
              "    <Name>B</Name>\n"
              "  </Vendor>\n"
              "  <Modules>\n"
              "    <Module>\n"
              "      <Type ModuleIdent=\"#x00000010\">M</Type>\n"
              "      <Name>M</Name>\n"
              "    </Module>\n"
              "  </Modules>\n"
              "</EtherCATModule>\n");
}

}  // namespace
