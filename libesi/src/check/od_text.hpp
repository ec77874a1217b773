#pragma once
// How pdo-… and od-… diagnostics spell what they talk about: object addresses as ESI files write
// them (#x6064, #x6064:00), so that a message can be searched for in the file, and the kind of
// value a basic type holds (a signed object described as UDINT reads -1 as 4294967295).

#include <cstdint>
#include <string>
#include <string_view>

#include "esi/data_types.hpp"
#include "esi/model/pdo.hpp"

namespace esi::rules {

[[nodiscard]] std::string object_address(std::uint32_t index);                       // "#x6064"
[[nodiscard]] std::string entry_address(std::uint32_t index, std::uint32_t subindex);  // "#x6064:00"
// "1 bit", "16 bits".
[[nodiscard]] std::string bits_text(std::uint64_t bits);
// "Entry #x6064:00", or "Entry 'Position'" when its Index could not be read.
[[nodiscard]] std::string entry_label(const PdoEntry& entry);

// What the bits of a value mean, as far as a master interpreting process data is concerned.
// BOOL, BITn, BYTE/WORD/DWORD and BITARRn all read as unsigned bit patterns.
enum class ValueKind { signed_integer, unsigned_integer, real, text, other };
[[nodiscard]] ValueKind value_kind(const BasicType& type);
[[nodiscard]] std::string_view to_string(ValueKind kind);

}  // namespace esi::rules
