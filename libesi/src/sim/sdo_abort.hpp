#pragma once
// SDO abort codes (ETG.1000.6 Table 41, after CiA 301 7.2.4.3.17) the CoE server answers with.

#include <cstdint>

namespace esi::sim::sdo_abort {

inline constexpr std::uint32_t none = 0;
inline constexpr std::uint32_t toggle_bit = 0x05030000;
inline constexpr std::uint32_t command_specifier = 0x05040001;
inline constexpr std::uint32_t unsupported_access = 0x06010000;
inline constexpr std::uint32_t write_only = 0x06010001;
inline constexpr std::uint32_t read_only = 0x06010002;
inline constexpr std::uint32_t subindex_0_not_zero = 0x06010003;  // SI0 must be 0 before writing the entries
inline constexpr std::uint32_t no_complete_access = 0x06010004;
inline constexpr std::uint32_t object_missing = 0x06020000;
inline constexpr std::uint32_t not_mappable = 0x06040041;
inline constexpr std::uint32_t pdo_length_exceeded = 0x06040042;
inline constexpr std::uint32_t length_mismatch = 0x06070010;
inline constexpr std::uint32_t length_too_long = 0x06070012;
inline constexpr std::uint32_t length_too_short = 0x06070013;
inline constexpr std::uint32_t subindex_missing = 0x06090011;
inline constexpr std::uint32_t value_range = 0x06090030;
inline constexpr std::uint32_t value_too_high = 0x06090031;
inline constexpr std::uint32_t general = 0x08000000;
inline constexpr std::uint32_t device_state = 0x08000022;

}  // namespace esi::sim::sdo_abort
