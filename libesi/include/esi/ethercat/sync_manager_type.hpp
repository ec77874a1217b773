#pragma once
// What a SyncManager carries. One numbering serves the SII's SyncM category (ETG.2010 Table 13,
// byte 7), the SM communication types object 0x1C00 (ETG.1000.6 5.6.7.4.8) and the ESI's Sm text
// (ETG.2000 Device/Sm: "MBoxOut", "MBoxIn", "Outputs", "Inputs").

#include <cstdint>
#include <optional>
#include <string_view>

namespace esi::ethercat {

enum class SyncManagerType : std::uint8_t { unused = 0, mailbox_out = 1, mailbox_in = 2, outputs = 3, inputs = 4 };

// The ESI text of a type ("" for unused); a text that is none of the four is nullopt.
[[nodiscard]] std::string_view sync_manager_type_name(SyncManagerType type);
[[nodiscard]] std::optional<SyncManagerType> parse_sync_manager_type(std::string_view esi_text);
// The code of the SII and of 0x1C00; a code above 4 is nullopt.
[[nodiscard]] std::optional<SyncManagerType> sync_manager_type_from_code(std::uint8_t code);

}  // namespace esi::ethercat
