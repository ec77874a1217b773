#pragma once
// A small but complete ESI file for the differ's unit tests: every part the model covers appears
// once, each with text that is unique in the file, so that a test makes the "new" revision by
// replacing one piece of text and checks what the differ reports.

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "esi/diff/classification.hpp"
#include "esi/diff/diff.hpp"
#include "esi/xml/reader.hpp"

namespace esi::test {

inline const char* const diff_base = R"(<?xml version="1.0" encoding="UTF-8"?>
<EtherCATInfo Version="1.17">
  <Vendor FileVersion="3">
    <Id>#x00000E4A</Id>
    <Name LcId="1033">Example Automation</Name>
    <URL LcId="1033">https://example.com</URL>
  </Vendor>
  <Descriptions>
    <Groups>
      <Group SortOrder="1">
        <Type>IO</Type>
        <Name LcId="1033">I/O terminals</Name>
      </Group>
      <Group>
        <Type>Drives</Type>
        <Name LcId="1033">Drives</Name>
      </Group>
    </Groups>
    <Devices>
      <Device Physics="YY">
        <Type ProductCode="#x00001001" RevisionNo="#x00010000">EX-1001</Type>
        <Name LcId="1033">Example device</Name>
        <Name LcId="1031">Beispielgerät</Name>
        <Comment LcId="1033">A device for tests</Comment>
        <Info><Electrical><EBusCurrent>120</EBusCurrent></Electrical></Info>
        <GroupType>IO</GroupType>
        <Profile>
          <ProfileNo>5001</ProfileNo>
          <Dictionary>
            <DataTypes>
              <DataType><Name>USINT</Name><BitSize>8</BitSize></DataType>
              <DataType><Name>UDINT</Name><BitSize>32</BitSize></DataType>
              <DataType>
                <Name>DT1A00</Name>
                <BitSize>80</BitSize>
                <SubItem><SubIdx>0</SubIdx><Name>Number of entries</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>0</BitOffs><Flags><Access>ro</Access></Flags></SubItem>
                <SubItem><SubIdx>1</SubIdx><Name>Entry 1</Name><Type>UDINT</Type><BitSize>32</BitSize><BitOffs>16</BitOffs><Flags><Access>ro</Access></Flags></SubItem>
                <SubItem><SubIdx>2</SubIdx><Name>Entry 2</Name><Type>UDINT</Type><BitSize>32</BitSize><BitOffs>48</BitOffs><Flags><Access>ro</Access></Flags></SubItem>
              </DataType>
              <DataType>
                <Name>DT8000</Name>
                <BitSize>48</BitSize>
                <SubItem><SubIdx>0</SubIdx><Name>Count</Name><Type>USINT</Type><BitSize>8</BitSize><BitOffs>0</BitOffs><Flags><Access>ro</Access></Flags></SubItem>
                <SubItem><SubIdx>1</SubIdx><Name>Filter</Name><Type>UDINT</Type><BitSize>32</BitSize><BitOffs>16</BitOffs><Flags><Access>rw</Access><PdoMapping>R</PdoMapping></Flags></SubItem>
              </DataType>
            </DataTypes>
            <Objects>
              <Object>
                <Index>#x1A00</Index>
                <Name>Inputs mapping</Name>
                <Type>DT1A00</Type>
                <BitSize>80</BitSize>
                <Info>
                  <SubItem><Name>Number of entries</Name><Info><DefaultValue>2</DefaultValue></Info></SubItem>
                  <SubItem><Name>Entry 1</Name><Info><DefaultValue>#x60000108</DefaultValue></Info></SubItem>
                  <SubItem><Name>Entry 2</Name><Info><DefaultValue>#x60000208</DefaultValue></Info></SubItem>
                </Info>
                <Flags><Access>ro</Access></Flags>
              </Object>
              <Object>
                <Index>#x6000</Index>
                <Name>Inputs</Name>
                <Type>USINT</Type>
                <BitSize>8</BitSize>
                <Flags><Access>ro</Access><PdoMapping>T</PdoMapping></Flags>
              </Object>
              <Object>
                <Index>#x7000</Index>
                <Name>Outputs</Name>
                <Type>UINT</Type>
                <BitSize>16</BitSize>
                <Info><DefaultValue>5</DefaultValue><MinValue>0</MinValue><MaxValue>1000</MaxValue></Info>
                <Flags><Access>rw</Access><PdoMapping>R</PdoMapping><Category>o</Category></Flags>
              </Object>
              <Object>
                <Index>#x8000</Index>
                <Name>Settings</Name>
                <Type>DT8000</Type>
                <BitSize>48</BitSize>
                <Info>
                  <SubItem><Name>Count</Name><Info><DefaultValue>1</DefaultValue></Info></SubItem>
                  <SubItem><Name>Filter</Name><Info><DefaultValue>100</DefaultValue></Info></SubItem>
                </Info>
                <Flags><Access>ro</Access></Flags>
              </Object>
            </Objects>
          </Dictionary>
        </Profile>
        <Fmmu>Outputs</Fmmu>
        <Fmmu>Inputs</Fmmu>
        <Sm StartAddress="#x1000" ControlByte="#x26" DefaultSize="128" MinSize="34" MaxSize="256" Enable="1">MBoxOut</Sm>
        <Sm StartAddress="#x1080" ControlByte="#x22" DefaultSize="128" MinSize="34" MaxSize="256" Enable="1">MBoxIn</Sm>
        <Sm StartAddress="#x1100" ControlByte="#x64" DefaultSize="2" Enable="1">Outputs</Sm>
        <Sm StartAddress="#x1400" ControlByte="#x20" DefaultSize="2" Enable="1">Inputs</Sm>
        <Su>Main</Su>
        <RxPdo Fixed="true" Sm="2">
          <Index>#x1600</Index>
          <Name>Outputs</Name>
          <Entry>
            <Index>#x7000</Index>
            <SubIndex>0</SubIndex>
            <BitLen>16</BitLen>
            <Name>Output value</Name>
            <DataType>UINT</DataType>
          </Entry>
        </RxPdo>
        <TxPdo Sm="3">
          <Index>#x1A00</Index>
          <Name>Inputs</Name>
          <Exclude>#x1A10</Exclude>
          <Entry>
            <Index>#x6000</Index>
            <SubIndex>1</SubIndex>
            <BitLen>8</BitLen>
            <Name>Input A</Name>
            <DataType>USINT</DataType>
          </Entry>
          <Entry>
            <Index>#x6000</Index>
            <SubIndex>2</SubIndex>
            <BitLen>8</BitLen>
            <Name>Input B</Name>
            <DataType>USINT</DataType>
          </Entry>
          <Entry>
            <Index>0</Index>
            <BitLen>4</BitLen>
          </Entry>
        </TxPdo>
        <TxPdo Sm="3">
          <Index>#x1A01</Index>
          <Name>Status</Name>
          <Entry>
            <Index>#x6010</Index>
            <SubIndex>1</SubIndex>
            <BitLen>16</BitLen>
            <Name>Status word</Name>
            <DataType>UINT</DataType>
          </Entry>
        </TxPdo>
        <TxPdo>
          <Index>#x1A10</Index>
          <Name>Diagnostics</Name>
          <Entry>
            <Index>#x6020</Index>
            <SubIndex>1</SubIndex>
            <BitLen>32</BitLen>
            <Name>Diag code</Name>
            <DataType>UDINT</DataType>
          </Entry>
        </TxPdo>
        <Mailbox DataLinkLayer="true">
          <EoE IP="true"/>
          <CoE SdoInfo="true" PdoAssign="true" CompleteAccess="false">
            <InitCmd>
              <Transition>PS</Transition>
              <Index>#x8000</Index>
              <SubIndex>1</SubIndex>
              <Data>64000000</Data>
              <Comment>filter</Comment>
            </InitCmd>
            <InitCmd>
              <Transition>PS</Transition>
              <Index>#x1C13</Index>
              <SubIndex>0</SubIndex>
              <Data>00</Data>
            </InitCmd>
          </CoE>
          <FoE/>
        </Mailbox>
        <Dc>
          <OpMode>
            <Name>DC</Name>
            <Desc>DC-Synchron</Desc>
            <AssignActivate>#x0300</AssignActivate>
            <CycleTimeSync0 Factor="1">0</CycleTimeSync0>
            <ShiftTimeSync0>0</ShiftTimeSync0>
          </OpMode>
          <OpMode>
            <Name>FreeRun</Name>
            <Desc>Free run</Desc>
            <AssignActivate>#x0000</AssignActivate>
          </OpMode>
        </Dc>
        <Slots MaxSlotCount="4">
          <Slot MinInstances="0" MaxInstances="2" SlotPdoIncrement="1">
            <Name>Axis slot</Name>
            <ModuleIdent Default="1">#x00001100</ModuleIdent>
            <ModuleIdent>#x00001200</ModuleIdent>
          </Slot>
        </Slots>
        <Eeprom>
          <ByteSize>2048</ByteSize>
          <ConfigData>080E00CC</ConfigData>
          <BootStrap>0010800080108000</BootStrap>
          <Category><CatNo>1</CatNo><Data>AABB</Data></Category>
        </Eeprom>
        <ImageData16x14>424D</ImageData16x14>
      </Device>
      <Device Physics="KK">
        <Type ProductCode="#x00002002" RevisionNo="#x00010000">EX-2002</Type>
        <Name LcId="1033">Second device</Name>
        <GroupType>IO</GroupType>
        <Sm StartAddress="#x1000" ControlByte="#x24" DefaultSize="1" Enable="1">Outputs</Sm>
        <RxPdo Fixed="true" Sm="0">
          <Index>#x1600</Index>
          <Name>Out</Name>
          <Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>1</BitLen><Name>Bit</Name><DataType>BOOL</DataType></Entry>
        </RxPdo>
      </Device>
    </Devices>
    <Modules>
      <Module>
        <Type ModuleIdent="#x00001100" ModuleClass="Axis">AX-1100</Type>
        <Name LcId="1033">Axis module</Name>
        <TxPdo Sm="3">
          <Index>#x1A40</Index>
          <Name>Axis status</Name>
          <Entry><Index>#x6040</Index><SubIndex>1</SubIndex><BitLen>16</BitLen><Name>Statusword</Name><DataType>UINT</DataType></Entry>
        </TxPdo>
      </Module>
      <Module>
        <Type ModuleIdent="#x00001200" ModuleClass="Axis">AX-1200</Type>
        <Name LcId="1033">Second axis module</Name>
      </Module>
    </Modules>
  </Descriptions>
</EtherCATInfo>
)";

// Replaces the one occurrence of `from`; a test whose edit does not apply fails loudly.
inline std::string edit(std::string text, std::string_view from, std::string_view to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "edit target not found: " << from;
    if (at == std::string::npos) return text;
    EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "edit target not unique: " << from;
    text.replace(at, from.size(), to);
    return text;
}

inline EsiDocument read_document(const std::string& xml) {
    ReadResult r = read_esi(xml, "test.xml");
    EXPECT_TRUE(r.document.has_value()) << (r.diagnostics.empty() ? std::string() : r.diagnostics.items()[0].message);
    return r.document ? std::move(*r.document) : EsiDocument{};
}

inline DiffResult diff_texts(const std::string& old_xml, const std::string& new_xml, const DiffOptions& options = {}) {
    return diff_documents(read_document(old_xml), read_document(new_xml), options);
}

inline std::string describe(const DiffResult& r) {
    std::string out;
    for (const auto& c : r.changes)
        out += std::string(to_string(c.change_class)) + " " + std::string(to_string(c.kind)) + " " + c.path + ": " + c.message +
               "\n";
    return out.empty() ? std::string("(no changes)\n") : out;
}

inline const Change* find_change(const DiffResult& r, ChangeKind kind) {
    for (const auto& c : r.changes)
        if (c.kind == kind) return &c;
    return nullptr;
}

}  // namespace esi::test
