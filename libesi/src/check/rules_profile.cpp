// Rules of the profile area: the limits a device family's manual states, declared in
// .esi-lint.yaml (limits:, or overrides with product_codes) and shipped for the seed families in
// samples/profiles/. Each rule checks one Limits field and is silent unless that field is set.
#include "check/areas.hpp"
#include "check/profile_checks.hpp"

namespace esi::rules {

void add_profile(std::vector<Rule>& out) {
    out.push_back(Rule{
        "profile-max-pdos", Severity::error, "More PDOs in a direction than the device supports (limits.max_pdos)",
        "Devices support a fixed number of PDOs: the item/Afag servo controllers 'unterstützt vier Receive-PDOs (RxPDO) und "
        "vier Transmit-PDOs (TxPDO)' (servo manuals §6.1.1, Tabelle 5), the STÖBER inverters 'vier PDO-Kanäle' (STÖBER "
        "manual §7.1). An ESI that declares more offers PDOs the firmware does not have. Set with "
        "`limits: { max_pdos: { rx: 4, tx: 4 } }`.",
        "limits: { max_pdos: { rx: 4 } } and five RxPdo elements", "limits: { max_pdos: { rx: 4 } } and four RxPdo elements",
        profile::check_max_pdos});
    out.push_back(Rule{
        "profile-pdo-index-range", Severity::error, "A PDO index outside the device's own index range (limits.pdo_index_ranges)",
        "Beyond the general ETG ranges, a device implements only its own mapping objects: 0x1600-0x1603 and "
        "0x1A00-0x1A03 for the item/Afag servo controllers (servo manuals §6.1.1, Tabelle 5, §6.1.2.5/6) and the STÖBER "
        "inverters (STÖBER manual §10.1, A225-A228/A233-A236). A PDO at 0x1604 maps an object the device does not have. "
        "Set with `limits: { pdo_index_ranges: { rx: [\"0x1600-0x1603\"], tx: [\"0x1A00-0x1A03\"] } }`.",
        "pdo_index_ranges: { rx: [\"0x1600-0x1603\"] } and <RxPdo><Index>#x1604</Index>",
        "pdo_index_ranges: { rx: [\"0x1600-0x1603\"] } and <RxPdo><Index>#x1603</Index>", profile::check_pdo_index_range});
    out.push_back(Rule{
        "profile-max-entries", Severity::error, "A PDO with more entries than the device can map (limits.max_entries_per_pdo)",
        "Mapping objects have a fixed number of sub-entries on many devices: the STÖBER inverters have 'einen Parameter mit "
        "sechs Subelementen' per PDO channel and direction (STÖBER manual §7.1.1), so a seventh entry is rejected with "
        "SDO abort 0x06040042. Padding entries occupy a mapping entry too and are counted. Set with "
        "`limits: { max_entries_per_pdo: 6 }`.",
        "max_entries_per_pdo: 6 and an RxPdo with 7 entries", "max_entries_per_pdo: 6 and an RxPdo with 6 entries",
        profile::check_max_entries});
    out.push_back(Rule{
        "profile-bitlen", Severity::error, "An entry BitLen the device cannot map (limits.bitlen)",
        "Some devices map only whole objects of certain widths: the item/Afag servo controllers accept BitLen 8, 16 or 32 "
        "(servo manuals Tabelle 14, §6.7.2). Bit-sized entries are then rejected when the master downloads the mapping. "
        "Padding entries (Index 0) are exempt. Set with `limits: { bitlen: [8, 16, 32] }`.",
        "bitlen: [8, 16, 32] and <Entry><Index>#x6040</Index><BitLen>1</BitLen>…",
        "bitlen: [8, 16, 32] and <Entry><Index>#x6040</Index><BitLen>16</BitLen>…", profile::check_bitlen});
    out.push_back(Rule{
        "profile-fixed-sm", Severity::error, "A SyncManager whose type differs from the device's fixed assignment (limits.fixed_sm)",
        "Many devices hard-wire the use of their SyncManagers: SM0 mailbox out, SM1 mailbox in, SM2 outputs, SM3 inputs, "
        "'fest und nicht durch den Anwender änderbar' on the item/Afag servo controllers (servo manuals §6.1.1, §6.1.2.2: "
        "0x1C00 = 1, 2, 3, 4) and the same roles on the STÖBER inverters (STÖBER manual §8.2, §10.1). An ESI that "
        "declares them differently makes the device reject the SM configuration. Set with "
        "`limits: { fixed_sm: { 0: MBoxOut, 1: MBoxIn, 2: Outputs, 3: Inputs } }`.",
        "fixed_sm: { 2: Outputs } and <Sm …>Inputs</Sm> as the third Sm", "fixed_sm: { 2: Outputs } and <Sm …>Outputs</Sm> as the third Sm",
        profile::check_fixed_sm});
    out.push_back(Rule{
        "profile-initcmd-transition", Severity::error, "An InitCmd at a transition the device does not support (limits.transitions)",
        "A device documents the state transitions it acts on: the item/Afag servo controllers list IP, PI, PS, SP, SO, "
        "OS, OP, SI and OI and implement no Bootstrap (servo manuals Tabelle 8, Tabelle 15, §6.2). An InitCmd at another "
        "transition is never executed or is refused. Set with `limits: { transitions: [IP, PS, SO] }`.",
        "transitions: [IP, PS, SO] and <InitCmd><Transition>IB</Transition>…",
        "transitions: [IP, PS, SO] and <InitCmd><Transition>PS</Transition>…", profile::check_initcmd_transition});
    out.push_back(Rule{
        "profile-initcmd-size", Severity::error, "A CoE InitCmd writes more bytes than the device accepts per SDO (limits.max_init_cmd_bytes)",
        "Some devices only support expedited SDO transfers: on the item/Afag servo controllers SDO access is limited to "
        "32 bits because only standard CANopen objects of at most 4 bytes can be accessed, and segmented transfers carry "
        "'max. 1 Segment mit 4 Byte Nutzdaten' (servo manuals §6.3, Tabelle 15); the STÖBER inverters transfer every "
        "parameter as a 4-byte integer (STÖBER manual §7.2). Longer InitCmd data is aborted at start-up. Set with "
        "`limits: { max_init_cmd_bytes: 4 }`.",
        "max_init_cmd_bytes: 4 and <InitCmd>…<Data>0000000000000000</Data></InitCmd>",
        "max_init_cmd_bytes: 4 and <InitCmd>…<Data>00000000</Data></InitCmd>", profile::check_initcmd_size});
    out.push_back(Rule{
        "profile-mailbox-size", Severity::error, "A mailbox SyncManager larger than the device supports (limits.max_mailbox_size)",
        "The mailbox size is limited by the ESC and the firmware's buffers: the AX58100 takes at most 128 bytes per "
        "mailbox (kubabuda/EEPROM_generator 'Truncate MailboxSize to 128 when AX58100 ESC was selected'; domain notes "
        "S7). A larger DefaultSize or MaxSize lets the master configure a mailbox the device overruns. Set with "
        "`limits: { max_mailbox_size: 128 }`.",
        "max_mailbox_size: 128 and <Sm DefaultSize=\"256\" …>MBoxOut</Sm>",
        "max_mailbox_size: 128 and <Sm DefaultSize=\"128\" …>MBoxOut</Sm>", profile::check_mailbox_size});
    out.push_back(Rule{
        "profile-absent-object", Severity::error, "An object the device does not have appears in the Dictionary, a PDO or an InitCmd (limits.absent_objects)",
        "Manuals list objects a device lacks: the item/Afag servo controllers have no 0x1008, 0x1009 or 0x100A "
        "('Objekt ist nicht vorhanden', servo manuals §6.1.2, Tabelle 6). An ESI that declares, maps or writes such an "
        "object promises what the device answers with SDO abort 0x06020000. Set with "
        "`limits: { absent_objects: [0x1008, 0x1009, 0x100A] }`.",
        "absent_objects: [0x1008] and <Object><Index>#x1008</Index>…", "absent_objects: [0x1008] and no object #x1008",
        profile::check_absent_object});
}

}  // namespace esi::rules
