// Rules of the pdo area: RxPdo/TxPdo of devices and modules and their entries. The checks live
// in pdo_*_checks.cpp; this file is the catalogue (see docs/rules.md).
#include "check/areas.hpp"
#include "check/pdo_checks.hpp"

namespace esi::rules {

void add_pdo(std::vector<Rule>& out) {
    out.push_back(Rule{
        "pdo-index-range", Severity::error, "RxPdo index outside 0x1600-0x17FF or TxPdo index outside 0x1A00-0x1BFF",
        "The PDO index is the index of its mapping object, and ETG.1000.6 reserves 0x1600-0x17FF for RxPDO mapping and "
        "0x1A00-0x1BFF for TxPDO mapping. A master that uploads or downloads the mapping (PdoAssign/PdoConfig) addresses "
        "exactly that object, and the SOES tutorial and both seed servo manuals (§6.1.1, Tabelle 5: RxPDOs 0x1600-0x1603, "
        "TxPDOs 0x1A00-0x1A03) rely on the split. An index in the other range usually means the PDO was declared with the "
        "wrong element (domain notes S16). Only devices with CoE are checked: without CoE there are no mapping objects "
        "and the index only names the PDO in the SII (SoE drives number their MDT/AT by IDN).",
        "<TxPdo Sm=\"3\"><Index>#x1600</Index><Name>Inputs</Name>…</TxPdo>",
        "<TxPdo Sm=\"3\"><Index>#x1A00</Index><Name>Inputs</Name>…</TxPdo>", pdo::check_index_range});
    out.push_back(Rule{
        "pdo-sm-unknown", Severity::error, "A PDO is assigned (Sm=) to a SyncManager the device does not declare",
        "Sm=\"n\" assigns the PDO by default to SyncManager n of the device's Sm list (ETG.2000 PdoType@Sm). When SM n does "
        "not exist the master has nowhere to put the process data: the SII PDO category points at a missing SM and TwinCAT "
        "refuses the configuration (domain notes S16; ETG.2010 PDO category 'SyncM').",
        "<Sm …>MBoxOut</Sm><Sm …>MBoxIn</Sm><Sm …>Outputs</Sm><RxPdo Sm=\"4\">…",
        "<Sm …>MBoxOut</Sm><Sm …>MBoxIn</Sm><Sm …>Outputs</Sm><RxPdo Sm=\"2\">…", pdo::check_sm_unknown});
    out.push_back(Rule{
        "pdo-sm-direction", Severity::error, "An RxPdo on an input SM or a TxPdo on an output SM",
        "RxPDOs carry outputs (master to slave) and must sit in an Outputs SyncManager (ControlByte direction 'write', "
        "usually SM2, #x24/#x64); TxPDOs carry inputs and belong to an Inputs SM (usually SM3, #x20). The seed servo "
        "manuals fix SM2 for RxPDOs and SM3 for TxPDOs (§6.1.1, Tabelle 13) and note that copying the RxPdo example "
        "literally would put a TxPdo on SM2. Process data on the wrong SM are never exchanged (domain notes S5, S16).",
        "<TxPdo Sm=\"2\"><Index>#x1A00</Index>…", "<TxPdo Sm=\"3\"><Index>#x1A00</Index>…", pdo::check_sm_direction});
    out.push_back(Rule{
        "pdo-duplicate-index", Severity::error, "Two PDOs of one device or module share an index",
        "A PDO index names one mapping object; two PDOs with the same index cannot both be assigned, and a master keeps "
        "only one of them (KickCAT warns on duplicate PDO indices; ETG.1000.6 one object per index). RxPdo and TxPdo "
        "share the index space.",
        "<RxPdo><Index>#x1600</Index>…</RxPdo><RxPdo><Index>#x1600</Index>…</RxPdo>",
        "<RxPdo><Index>#x1600</Index>…</RxPdo><RxPdo><Index>#x1601</Index>…</RxPdo>", pdo::check_duplicate_index});
    out.push_back(Rule{
        "pdo-exclude-unknown", Severity::warning, "Exclude names a PDO that does not exist",
        "Exclude lists the PDOs that cannot be assigned together with this one (ETG.2000 PdoType/Exclude); configuration "
        "tools grey them out. An Exclude that names no PDO of the device is a typo or a leftover from a removed PDO, and "
        "the exclusion it was meant to express is lost. Slot-dependent excludes (DependOnSlot) are not checked.",
        "<RxPdo><Index>#x1600</Index><Exclude>#x1610</Exclude>…</RxPdo> (no PDO #x1610)",
        "<RxPdo><Index>#x1600</Index><Exclude>#x1601</Exclude>…</RxPdo><RxPdo><Index>#x1601</Index>…</RxPdo>",
        pdo::check_exclude_unknown});
    out.push_back(Rule{
        "pdo-mapping-limits", Severity::error, "More than 255 entries in a PDO, BitLen 0 or above 255, or more than 255 PDOs",
        "The CoE mapping objects count their entries in the 8-bit sub-index 0 and store each entry's length in 8 bits; the "
        "assignment objects 0x1C1x likewise list at most 255 PDOs (ETG.1000.6 PDO mapping/assignment; the SII PDO category "
        "of ETG.2010 has one-byte counts too). KickCAT rejects such files ('>255 entries', 'BitLen > 255'); domain notes S19. "
        "A BitLen of 0 on an object maps nothing; padding entries with BitLen 0 (a zero-width gap, found in a Beckhoff "
        "module file of the corpus) are harmless and not reported.",
        "<Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>512</BitLen>…</Entry>",
        "<Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>32</BitLen>…</Entry>", pdo::check_mapping_limits});
    out.push_back(Rule{
        "pdo-entry-type-unknown", Severity::error, "A PDO entry's DataType is not an ESI type name",
        "Masters type process variables from the entry's DataType. A name that is neither a basic ESI type (ETG.2000, "
        "ET9300 Table 22: BOOL, USINT, UINT, UDINT, …) nor defined in the Dictionary cannot be typed; generators such as "
        "pollen-robotics/pyesi write C-style names (UINT8, UINT16) that TwinCAT does not know (domain notes S30). The "
        "message names the standard spelling when there is one.",
        "<Entry><Index>#x6041</Index><BitLen>16</BitLen><DataType>UINT16</DataType></Entry>",
        "<Entry><Index>#x6041</Index><BitLen>16</BitLen><DataType>UINT</DataType></Entry>", pdo::check_entry_type_unknown});
    out.push_back(Rule{
        "pdo-entry-bitlen-type", Severity::error, "A PDO entry's BitLen disagrees with its DataType",
        "BitLen is the width the entry occupies in the process image and DataType says how to read it; UINT is 16 bits, "
        "DINT 32, BITn n (ET9300 Table 22; ETG.1000.6 data types). A mismatch shifts every later variable in the image "
        "or truncates the value. The seed servo manuals state it outright: BitLen 'muss immer dem Typ … entsprechen' "
        "(Tabelle 14). Padding entries (Index 0) are exempt.",
        "<Entry><Index>#x6064</Index><BitLen>16</BitLen><DataType>DINT</DataType></Entry>",
        "<Entry><Index>#x6064</Index><BitLen>32</BitLen><DataType>DINT</DataType></Entry>", pdo::check_entry_bitlen_type});
    out.push_back(Rule{
        "pdo-entry-object-missing", Severity::warning, "A PDO entry maps an object or sub-index the Dictionary does not contain",
        "A PDO entry maps Dictionary object Index:SubIndex. When the device ships its Dictionary in the ESI, a mapped object "
        "that is not in it cannot be configured over SDO: the device answers abort 0x06020000 'object does not exist' "
        "(OpenEtherCATsociety/SOEM #402) or 0x06040041 'cannot be mapped' (STÖBER manual §7.2.3). Checked only for devices "
        "whose own Dictionary lists objects; modules, modular devices and slot-dependent indices (DependOnSlot) take "
        "objects from elsewhere, oversampling PDOs shift their indices, and objects that ETG profiles define (0x10F0-0x10FF, "
        "TxPDO parameters 0x1800-0x19FF, the modular device area 0xF000-0xFFFF) are known to masters without the ESI "
        "(domain notes S17; servo manuals D7).",
        "<Entry><Index>#x6064</Index>…</Entry> with no Object #x6064",
        "<Object><Index>#x6064</Index>…</Object> … <Entry><Index>#x6064</Index>…</Entry>", pdo::check_entry_object_missing});
    out.push_back(Rule{
        "pdo-entry-object-type", Severity::error, "A PDO entry's DataType differs in kind (signedness) from the object it maps",
        "The entry's DataType is what the master uses to interpret the bits; the object's type is what the firmware puts "
        "there. A signed object described as UDINT reads -1 as 4294967295, and a REAL described as DINT is garbage. A "
        "generator that chose the DataType by bit width alone shipped exactly this and the device still reached OP "
        "(domain notes S17, §1.12 gen_od review; KickCAT mapping_target_subindex_reconciled_against_object). Types of the "
        "same kind and width (UINT/WORD, BOOL/BIT1) are accepted.",
        "<Object><Index>#x6064</Index><Type>DINT</Type>… <Entry><Index>#x6064</Index><BitLen>32</BitLen><DataType>UDINT</DataType>",
        "<Object><Index>#x6064</Index><Type>DINT</Type>… <Entry><Index>#x6064</Index><BitLen>32</BitLen><DataType>DINT</DataType>",
        pdo::check_entry_object_type});
    out.push_back(Rule{
        "pdo-entry-object-bitlen", Severity::error, "A PDO entry's BitLen differs from the size of the object it maps",
        "The device fills the process image with the object's own size; an ESI entry with another BitLen makes the master "
        "read a different layout than the slave writes (STÖBER manual §7.1.1: the device reports the mapped length; "
        "SDO abort 0x06040042 'length exceeds PDO'). Reported only when BitLen agrees with the entry's own DataType "
        "(otherwise pdo-entry-bitlen-type reports it) (domain notes S17).",
        "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>16</BitSize>… <Entry><Index>#x6041</Index><BitLen>8</BitLen>",
        "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>16</BitSize>… <Entry><Index>#x6041</Index><BitLen>16</BitLen>",
        pdo::check_entry_object_bitlen});
    out.push_back(Rule{
        "pdo-entry-not-mappable", Severity::warning, "A PDO entry maps an object whose PdoMapping flag forbids that direction",
        "Objects declare whether they may be mapped into RxPDOs (R), TxPDOs (T) or both (Flags/PdoMapping, ETG.2000 "
        "ObjectType; lower case marks optional mapping). A device rejects a mapping of any other object with SDO abort "
        "0x06040041 'object cannot be mapped into the PDO' (STÖBER manual §7.1.1, §7.2.3: only parameters marked 'PDO' "
        "can be mapped); the SSC spreadsheet's rx/tx column has the same meaning (ET9300 §13). Objects without any "
        "PdoMapping flag are not reported: many generators omit the flag altogether.",
        "<Object><Index>#x6041</Index>…<Flags><PdoMapping>T</PdoMapping></Flags></Object> mapped into an RxPdo",
        "<Object><Index>#x6040</Index>…<Flags><PdoMapping>R</PdoMapping></Flags></Object> mapped into an RxPdo",
        pdo::check_entry_not_mappable});
    out.push_back(Rule{
        "pdo-padding-subindex", Severity::warning, "A padding entry (Index 0) with a SubIndex other than 0",
        "Gaps in a PDO are mapped as Index 0, SubIndex 0 with the gap's BitLen (SOEM #297: fillers are 0x0000:00; SSC "
        "pad_x entries). A non-zero SubIndex turns the filler into the mapping entry 0x0000:nn, which some slave stacks "
        "reject when the mapping is downloaded. Padding needs neither a DataType nor a Name (domain notes S18).",
        "<Entry><Index>#x0</Index><SubIndex>1</SubIndex><BitLen>7</BitLen></Entry>",
        "<Entry><Index>#x0</Index><BitLen>7</BitLen></Entry>", pdo::check_padding_subindex});
    out.push_back(Rule{
        "pdo-entry-alignment", Severity::warning, "An entry of 8 bits or more does not start on a byte boundary",
        "Values of a byte or more should start on a byte boundary of the PDO; many slave stacks copy process data byte-wise "
        "and masters map variables to byte offsets, so a 16-bit value at bit 3 is either rejected or read shifted. The "
        "SSC inserts padding for this reason ('append padding byte', cia402appl.h), and domain notes S18 list it. Only "
        "the first misaligned entry of a PDO is reported, as the others follow from it.",
        "<Entry><Index>#x6000</Index><SubIndex>1</SubIndex><BitLen>1</BitLen>…</Entry><Entry><Index>#x6001</Index><BitLen>16</BitLen>…",
        "<Entry><Index>#x6000</Index><SubIndex>1</SubIndex><BitLen>1</BitLen>…</Entry><Entry><Index>#x0</Index><BitLen>7</BitLen></Entry>"
        "<Entry><Index>#x6001</Index><BitLen>16</BitLen>…",
        pdo::check_entry_alignment});
    out.push_back(Rule{
        "pdo-assign-default", Severity::warning, "The default of 0x1C12/0x1C13 differs from the PDOs assigned by Sm=",
        "PDOs with Sm=\"n\" are assigned to SM n by default; the Dictionary states the same assignment as the default of "
        "object 0x1C10+n (0x1C12 for SM2, 0x1C13 for SM3; ETG.1000.6). A master that uploads the assignment (PdoUpload) "
        "and one that takes it from the ESI then build different process images; SSC-generated firmware with byte-swapped "
        "or stale 0x1C12 defaults is a classic field failure (SOEM #402; domain notes S23). Modular devices are skipped: "
        "their assignment grows with the plugged modules. The order is not compared, only which PDOs are assigned.",
        "<RxPdo Sm=\"2\"><Index>#x1600</Index>… with 0x1C12 default listing #x1601",
        "<RxPdo Sm=\"2\"><Index>#x1600</Index>… with 0x1C12 default listing #x1600", pdo::check_assign_default});
    out.push_back(Rule{
        "pdo-mapping-default", Severity::warning, "A mapping object's default (0x16xx/0x1Axx) differs from the PDO's entries",
        "The default value of mapping object 0x16xx/0x1Axx sub-index k is the k-th entry of the PDO encoded as "
        "index<<16 | subindex<<8 | bit length (ETG.1000.6; STÖBER manual §7.1.1 shows the byte layout). When it disagrees "
        "with the ESI entries, a master that reads the mapping from the device and one that trusts the ESI exchange "
        "differently laid out data (domain notes S23; KickCAT synthesises these objects from the PDOs for that reason).",
        "<RxPdo><Index>#x1600</Index><Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>8</BitLen>… with 0x1600:01 "
        "default #x70000110",
        "<RxPdo><Index>#x1600</Index><Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>8</BitLen>… with 0x1600:01 "
        "default #x70000108",
        pdo::check_mapping_default});
}

}  // namespace esi::rules
