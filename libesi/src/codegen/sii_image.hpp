#pragma once
// The SII EEPROM image of a device as an esi-gen output, so that the image, the ESI and the
// firmware tables come from one source and cannot drift apart (issue 5 §1: "esi-gen also writes
// the image next to the other outputs").

#include <string>

#include "esi/codegen/generate.hpp"

namespace esi::codegen {

// Raw binary image, as `ethercat sii_write` and SOEM's eepromtool -w take it.
[[nodiscard]] Diagnostics produce_sii_binary(const ProduceContext& context, std::string& content);
// The same image as Intel HEX, for EEPROM programmers.
[[nodiscard]] Diagnostics produce_sii_intel_hex(const ProduceContext& context, std::string& content);

}  // namespace esi::codegen
