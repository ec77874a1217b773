#pragma once
// A small, complete ESI device for the SII unit tests: mailbox (CoE with flags, FoE, EoE),
// SyncManagers, FMMUs, PDOs, DC op modes (one legacy), Eeprom with ConfigData, BootStrap and a
// vendor category, EBusCurrent, Physics with an E-Bus port.

#include <gtest/gtest.h>

#include <string>

#include "esi/sii/build.hpp"
#include "esi/xml/reader.hpp"

namespace esi::test {

inline std::string fixture_xml(const std::string& eeprom_extra = {}, const std::string& byte_size = "2048",
                               const std::string& device_extra = {}) {
    return R"(<?xml version="1.0" encoding="UTF-8"?>
<EtherCATInfo Version="1.6">
  <Vendor><Id>#x0000ABCD</Id><Name>Test Vendor</Name></Vendor>
  <Descriptions>
    <Groups><Group><Type>TestGroup</Type><Name LcId="1033">Test devices</Name></Group></Groups>
    <Devices>
      <Device Physics="YYK">
        <Type ProductCode="#x00001234" RevisionNo="#x00020001">TD-100</Type>
        <Name LcId="1033">Test device 100</Name>
        <Name LcId="1031">Testgerät 100</Name>
        <Info><Electrical><EBusCurrent>-150</EBusCurrent></Electrical></Info>
        <GroupType>TestGroup</GroupType>
        <Fmmu>Outputs</Fmmu>
        <Fmmu>Inputs</Fmmu>
        <Fmmu>MBoxState</Fmmu>
        <Sm StartAddress="#x1000" ControlByte="#x26" DefaultSize="128" Enable="1">MBoxOut</Sm>
        <Sm StartAddress="#x1080" ControlByte="#x22" DefaultSize="128" Enable="1">MBoxIn</Sm>
        <Sm StartAddress="#x1100" ControlByte="#x64" DefaultSize="4" Enable="1" OpOnly="1">Outputs</Sm>
        <Sm StartAddress="#x1180" ControlByte="#x20" Enable="1" Virtual="1">Inputs</Sm>
        <RxPdo Fixed="1" Mandatory="1" Sm="2">
          <Index>#x1600</Index><Name>Outputs</Name>
          <Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>16</BitLen><Name>Setpoint</Name><DataType>INT</DataType></Entry>
          <Entry><Index>0</Index><BitLen>16</BitLen></Entry>
        </RxPdo>
        <TxPdo Sm="3">
          <Index>#x1A00</Index><Name>Inputs</Name>
          <Entry><Index>#x6000</Index><SubIndex>1</SubIndex><BitLen>32</BitLen><Name>Position µm</Name><DataType>DINT</DataType></Entry>
          <Entry><Index>#x6000</Index><SubIndex>2</SubIndex><BitLen>8</BitLen><Name>Label</Name><DataType>STRING(1)</DataType></Entry>
        </TxPdo>
        <TxPdo>
          <Index>#x1A01</Index><Name>Optional</Name>
        </TxPdo>
        <Mailbox DataLinkLayer="true">
          <CoE SdoInfo="true" PdoAssign="true" PdoConfig="false" CompleteAccess="true"/>
          <FoE/>
          <EoE/>
        </Mailbox>
        <Dc>
          <OpMode>
            <Name>DcSync</Name><Desc>SYNC0</Desc><AssignActivate>#x0300</AssignActivate>
            <CycleTimeSync0 Factor="1">1000000</CycleTimeSync0>
            <ShiftTimeSync0>-2500</ShiftTimeSync0>
            <CycleTimeSync1 Factor="-2">0</CycleTimeSync1>
            <ShiftTimeSync1>7000</ShiftTimeSync1>
          </OpMode>
          <OpMode>
            <Name>DcOld</Name><AssignActivate>#x0700</AssignActivate>
            <VendorSpecific><TwinCAT IgnoreFromBuildNo="1506"/></VendorSpecific>
          </OpMode>
          <OpMode><Name>FreeRun</Name><AssignActivate>#x0000</AssignActivate></OpMode>
        </Dc>
        <Eeprom>
          )" + (byte_size.empty() ? std::string() : "<ByteSize>" + byte_size + "</ByteSize>") + R"(
          <ConfigData>0E05030610270000</ConfigData>
          <BootStrap>0010000200120002</BootStrap>
          )" + eeprom_extra + R"(
        </Eeprom>
        )" + device_extra + R"(
      </Device>
    </Devices>
  </Descriptions>
</EtherCATInfo>
)";
}

struct Fixture {
    EsiDocument document;
    const EtherCATInfo& info() const { return document.infos.front(); }
    const Device& device() const { return document.infos.front().devices.front(); }
};

inline Fixture load_fixture(const std::string& xml) {
    ReadResult read = read_esi(xml, "fixture.xml");
    EXPECT_TRUE(read.document.has_value());
    for (const auto& d : read.diagnostics) EXPECT_NE(d.severity, Severity::error) << d.message;
    return Fixture{std::move(*read.document)};
}

inline sii::BuildResult build_fixture(const std::string& xml, const sii::BuildOptions& options = {}) {
    const Fixture f = load_fixture(xml);
    return sii::build_image(f.info(), f.device(), options, "fixture.xml");
}

inline bool has_rule(const Diagnostics& diagnostics, const std::string& rule, Severity severity) {
    for (const auto& d : diagnostics)
        if (d.rule == rule && d.severity == severity) return true;
    return false;
}

}  // namespace esi::test
