// Rules of the od area: the Dictionary (DataTypes and Objects) of devices, modules and
// EtherCATDict files. The checks live in od_*_checks.cpp; this file is the catalogue.
#include "check/areas.hpp"
#include "check/od_checks.hpp"

namespace esi::rules {

void add_od(std::vector<Rule>& out) {
    out.push_back(Rule{
        "od-type-unresolved", Severity::error, "An Object, SubItem or BaseType names a type that is not defined",
        "Every Object/Type, SubItem/Type and BaseType must name a basic ESI type or a DataType of the same Dictionary; the "
        "ETG schema states this as the keyrefs ObjectTypesRef, SubItemTypeRef and BaseTypeRef (ETG.2000 EtherCATBase.xsd). "
        "A type that does not resolve has no size and no sub-entries, so masters cannot read the object and generators "
        "cannot lay it out (KickCAT: 'unresolved Type reference'). Reported once per missing name.",
        "<Object><Index>#x6000</Index><Type>DT6000</Type>…</Object> with no DataType DT6000",
        "<DataType><Name>DT6000</Name>…</DataType> … <Object><Index>#x6000</Index><Type>DT6000</Type>…</Object>",
        od::check_type_unresolved});
    out.push_back(Rule{
        "od-type-cycle", Severity::error, "DataTypes whose BaseType chain loops",
        "A DataType refers to its base through BaseType; a chain that comes back to where it started has no base at all, "
        "and a naive resolver recurses forever (KickCAT test throws_on_basetype_cycle limits the depth for this reason; "
        "domain notes S21).",
        "<DataType><Name>DT_A</Name><BaseType>DT_B</BaseType>…</DataType><DataType><Name>DT_B</Name><BaseType>DT_A</BaseType>…",
        "<DataType><Name>DT_A</Name><BaseType>UINT</BaseType><BitSize>16</BitSize></DataType>", od::check_type_cycle});
    out.push_back(Rule{
        "od-nonstandard-type-name", Severity::error, "A type named with a non-standard spelling (UINT16 instead of UINT)",
        "ESI type names are the IEC 61131-3 style names of ETG.2000 and ET9300 Table 22 (USINT, UINT, UDINT, SINT, INT, "
        "DINT, BOOL, REAL, …). C-style spellings such as UINT8/UINT16/UINT32 or CoE names such as UNSIGNED16 are not "
        "understood by TwinCAT or the conformance test tool; generators such as pollen-robotics/pyesi emit them (domain "
        "notes S30). The message names the standard spelling. A Dictionary may define a DataType of such a name; "
        "only names that nothing defines are reported.",
        "<Object><Index>#x6041</Index><Type>UINT16</Type><BitSize>16</BitSize></Object>",
        "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>16</BitSize></Object>", od::check_nonstandard_type_name});
    out.push_back(Rule{
        "od-subitem-layout", Severity::error, "DataType SubItems that overlap or extend past the DataType's BitSize",
        "The SubItems of a record type are laid out by BitOffs and BitSize inside the type's BitSize (ETG.2000 "
        "DataTypeType). Overlapping SubItems make two sub-entries share bits, and a SubItem past the end reads beyond the "
        "object; complete-access SDO transfers and generated structs then disagree with the device (domain notes S21; "
        "KickCAT layout checks). Overlaps are checked between sub-indices (SubItems with SubIdx) only, since SoE "
        "dictionaries describe unions with overlapping structure members; one finding per DataType.",
        "<DataType><Name>DT2000</Name><BitSize>32</BitSize><SubItem><Name>A</Name><Type>UINT</Type><BitSize>16</BitSize>"
        "<BitOffs>16</BitOffs></SubItem><SubItem><Name>B</Name><Type>UINT</Type><BitSize>16</BitSize><BitOffs>24</BitOffs>…",
        "<DataType><Name>DT2000</Name><BitSize>48</BitSize><SubItem><Name>A</Name><Type>UINT</Type><BitSize>16</BitSize>"
        "<BitOffs>16</BitOffs></SubItem><SubItem><Name>B</Name><Type>UINT</Type><BitSize>16</BitSize><BitOffs>32</BitOffs>…",
        od::check_subitem_layout});
    out.push_back(Rule{
        "od-array-size", Severity::error, "An array DataType whose ArrayInfo disagrees with its BitSize",
        "An array type's BitSize is the number of elements (ArrayInfo/Elements) times the size of its BaseType (ETG.2000 "
        "ArrayInfo). When they disagree, the number of sub-indices or their offsets is wrong; KickCAT rejects such types "
        "('array BitSize not divisible by elements', test throws_on_array_bitsize_not_divisible_by_elements) (domain notes "
        "S20, S21). Elements 0 with BitSize 0 (an empty PDO assignment list) is consistent.",
        "<DataType><Name>DT1C12ARR</Name><BaseType>UINT</BaseType><BitSize>48</BitSize><ArrayInfo><LBound>1</LBound>"
        "<Elements>2</Elements></ArrayInfo></DataType>",
        "<DataType><Name>DT1C12ARR</Name><BaseType>UINT</BaseType><BitSize>32</BitSize><ArrayInfo><LBound>1</LBound>"
        "<Elements>2</Elements></ArrayInfo></DataType>",
        od::check_array_size});
    out.push_back(Rule{
        "od-bitsize", Severity::warning, "An Object's or SubItem's BitSize disagrees with its type",
        "BitSize states the size of the object or sub-item; the type states it too (UINT is 16 bits, STRING(10) 80, a "
        "DataType its own BitSize; ET9300 Table 22, ETG.2000 ObjectType/BitSize). When they differ, SDO uploads, "
        "complete access and generated object tables disagree about the object's length (domain notes S20). A DataType "
        "named like a basic type (Beckhoff lists <DataType><Name>UINT</Name><BitSize>16</BitSize>) must have that size.",
        "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>32</BitSize></Object>",
        "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>16</BitSize></Object>", od::check_bitsize});
    out.push_back(Rule{
        "od-duplicate-datatype", Severity::error, "Two DataTypes of one Dictionary share a name",
        "DataType names are the keys objects use to refer to types; the ETG schema requires them to be unique "
        "(EtherCATBase.xsd key DataTypeKey). With two definitions, tools pick either one and may lay the object out "
        "differently.",
        "<DataType><Name>DT6000</Name><BitSize>24</BitSize>…</DataType><DataType><Name>DT6000</Name><BitSize>48</BitSize>…",
        "<DataType><Name>DT6000</Name><BitSize>24</BitSize>…</DataType><DataType><Name>DT6010</Name><BitSize>48</BitSize>…",
        od::check_duplicate_datatype});
    out.push_back(Rule{
        "od-mandatory-object", Severity::error, "A CoE device's Dictionary lacks object 0x1000 or 0x1018",
        "Every CoE device has Device type (0x1000) and Identity (0x1018) (ETG.1000.6; CiA 301); the conformance test "
        "tool reads both (CTT TF-2301) and masters compare 0x1018 with the ESI identity. When the ESI describes the "
        "Dictionary, it must describe these objects too (SOES tutorial; domain notes S22). Devices whose ESI has no "
        "Dictionary are not checked.",
        "<Mailbox><CoE/></Mailbox> and a Dictionary with objects but no #x1018",
        "<Mailbox><CoE/></Mailbox> and a Dictionary with #x1000 and #x1018", od::check_mandatory_object});
    out.push_back(Rule{
        "od-duplicate-object", Severity::error, "Two Objects of one Dictionary share an index",
        "An index addresses one object (ETG.1000.6 object dictionary). With two declarations a master shows one and the "
        "other is unreachable; slave tables generated from the ESI have two entries for one index and SDO lookups such as "
        "SOES's sorted SDO_findobject pick either (domain notes S25).",
        "<Object><Index>#x2000</Index>…</Object><Object><Index>#x2000</Index>…</Object>",
        "<Object><Index>#x2000</Index>…</Object><Object><Index>#x2001</Index>…</Object>", od::check_duplicate_object});
    out.push_back(Rule{
        "od-flags-value", Severity::error, "An Access, PdoMapping or Category value the schema does not allow",
        "Flags/Access is ro, rw or wo; Flags/PdoMapping is R, T, RT or TR (lower case for optional mapping); "
        "Flags/Category is m, o or c (ETG.2000 EtherCATBase.xsd ObjectType/Flags). Other spellings (RW, R/W, rx) are "
        "read as 'no access' or 'not mappable' by tools that follow the schema.",
        "<Flags><Access>RW</Access><PdoMapping>rx</PdoMapping></Flags>",
        "<Flags><Access>rw</Access><PdoMapping>R</PdoMapping></Flags>", od::check_flags_value});
    out.push_back(Rule{
        "od-default-length", Severity::warning, "DefaultData/MinData/MaxData whose length differs from the entry's size",
        "DefaultData, MinData and MaxData are the value's bytes as an SDO transfers them (ETG.2000 ObjectInfoType), so "
        "they have exactly the entry's size in bytes; strings and byte arrays may be shorter than their maximum. A "
        "longer or shorter value is truncated or padded differently by each tool (KickCAT 'data default size mismatch'; "
        "kubabuda/EEPROM_generator #2 on string lengths; domain notes S20). DefaultString must fit STRING(n).",
        "<Object><Index>#x1018</Index>… <SubItem><Name>Vendor ID</Name><Info><DefaultData>E40A</DefaultData>…",
        "<Object><Index>#x1018</Index>… <SubItem><Name>Vendor ID</Name><Info><DefaultData>E40A0000</DefaultData>…",
        od::check_default_length});
    out.push_back(Rule{
        "od-default-range", Severity::warning, "A default value outside MinValue/MaxValue or outside its type",
        "A device starts with its default; a default that its own limits forbid (or that does not fit the type, such as "
        "300 for a USINT) is either rejected by the firmware's range check at the first SDO write-back or silently "
        "truncated. MinValue above MaxValue is reported too. Limits of signed objects written as bit patterns "
        "(#xfff80001 for a DINT) are read as two's complement (ETG.2000 ObjectInfoType; SSC Default/Min/Max columns, "
        "ET9300 §13).",
        "<Type>USINT</Type>… <Info><DefaultValue>300</DefaultValue></Info>",
        "<Type>USINT</Type>… <Info><DefaultValue>30</DefaultValue></Info>", od::check_default_range});
}

}  // namespace esi::rules
