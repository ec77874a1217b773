#pragma once
// How ESI values map to SII fields. The builder writes with these and the checker compares
// with them, so the two can never disagree. Sources per function; docs/sii.md has the choices.

#include <cstdint>
#include <optional>
#include <string_view>

#include "esi/model/device.hpp"

namespace esi::sii {

// SyncM type byte of an Sm text: MBoxOut 1, MBoxIn 2, Outputs/DynamicOutputs 3,
// Inputs/DynamicInputs 4, empty 0 (ETG.2010 SyncM category); nullopt when unknown.
[[nodiscard]] std::optional<std::uint8_t> sm_type_code(std::string_view sm_text);
// FMMU usage byte of an Fmmu text: Outputs/DynamicOutputs 1, Inputs/DynamicInputs 2,
// MBoxState 3, empty 0 (ETG.1000.6 Table 23); nullopt when unknown.
[[nodiscard]] std::optional<std::uint8_t> fmmu_usage_code(std::string_view fmmu_text);
// Port nibble of one Physics letter: Y and H (MII) 1, K (E-Bus) 3, space 0; nullopt when
// unknown (digest §4.3 S13, EEPROM_generator getPhysicalPort).
[[nodiscard]] std::optional<std::uint8_t> port_code(char physics_letter);
// SyncM enable byte: the Enable value, bit 1 FixedAssignment, bit 2 Virtual, bit 3 OpOnly
// (ETG.2010; the EL2004 image holds 0x09 for Enable="1" OpOnly="1").
[[nodiscard]] std::uint8_t sm_enable_byte(const SyncManager& sm);
// SyncM length: DefaultSize, else 0 (Beckhoff's images leave process-data SMs at 0).
[[nodiscard]] std::uint16_t sm_length(const SyncManager& sm);
// General byte 5: bit 0 SDO (CoE present), 1 SdoInfo, 2 PdoAssign, 3 PdoConfig, 4 PdoUpload,
// 5 CompleteAccess.
[[nodiscard]] std::uint8_t coe_details_byte(const Mailbox& mailbox);
// TxPDO/RxPDO header flags: Mandatory, Fixed, Virtual, DependOnSlot(Group), OverwrittenByModule.
[[nodiscard]] std::uint16_t pdo_flags(const Pdo& pdo);
// The one-byte SII data type of a PDO entry (its CoE code when < 0x100; STRING(n) 0x09,
// ARRAY OF BYTE/USINT 0x0A); falls back to the Dictionary object the entry maps when the entry
// names no type. nullopt when there is none.
[[nodiscard]] std::optional<std::uint8_t> pdo_entry_data_type(const Device& device, const PdoEntry& entry);
// Two one-byte SII data types that describe the same PDO entry: equal, or a bit string and the
// unsigned integer of its width (BYTE/USINT, WORD/UINT, DWORD/UDINT): Beckhoff's EL2262 image
// writes USINT (0x05) for an entry the ESI types BYTE (0x1E).
[[nodiscard]] bool same_pdo_data_type(std::uint8_t esi_code, std::uint8_t image_code);
// A DC op mode the vendor marks as ignored by current TwinCAT builds
// (VendorSpecific/TwinCAT@IgnoreFromBuildNo): legacy modes Beckhoff's own EEPROMs leave out.
[[nodiscard]] bool is_legacy_op_mode(const DcOpMode& op_mode);
// Info/Electrical/EBusCurrent in mA, when present and a number.
[[nodiscard]] std::optional<std::int64_t> ebus_current(const Device& device);
// The standard mailbox SMs (first Sm of type MBoxOut / MBoxIn).
[[nodiscard]] const SyncManager* find_sm(const Device& device, std::string_view type);

}  // namespace esi::sii
