#pragma once
// SDO Information (ETG.1000.6 5.6.3): the object list, object descriptions and entry
// descriptions a master (SOEM's ecx_readODlist, ecx_readODdescription, ecx_readOE) asks for, in
// fragments when a response does not fit the mailbox.

#include <cstdint>
#include <span>
#include <vector>

#include "sim/coe_dictionary.hpp"

namespace esi::sim {

// `request` is the SDO Information part of a CoE frame (after the 2-byte CoE header); the result
// is the responses' SDO Information parts, each at most `room` bytes, in the order to send.
[[nodiscard]] std::vector<std::vector<std::uint8_t>> sdo_info_response(const CoeDictionary& dictionary,
                                                                       std::span<const std::uint8_t> request,
                                                                       std::size_t room);

}  // namespace esi::sim
