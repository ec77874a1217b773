#pragma once
// The C names of igh_config.h/.c (docs/esi-net.md, "IgH"): one scheme for every slave and
// entry, so that a program reads `<slave>_<pdo>_<entry>` wherever an entry name repeats
// in a slave and `<slave>_<entry>` where it does not — never both for one name.
//
//   slave      the slave's name as a C identifier (lower case, runs of other characters as
//              one '_', "s_" in front of a leading digit); a second slave with the same
//              identifier gets "_<position>"
//   entry      <slave>_<entry name>; when the entry name (as an identifier) occurs more than
//              once among the slave's registered entries, every one of them is
//              <slave>_<PDO name>_<entry name>; an unnamed entry is named by its index and
//              sub-index (<slave>_6000_01); a name still taken (identifiers made alike by the
//              conversion, or equal to a name of another slave or of the network) gets
//              "_<index>_<sub-index>" in hex, then a number
//   network    <network>_domain_regs, <network>_configure, <network>_dc_sync
//
// Every name is a valid C identifier, unique in the two files (with its "_bit" companion),
// and depends only on the network, so the files are the same for the same network.

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "esi/net/network.hpp"

namespace esi::net {

// Lower case ASCII letters and digits, runs of anything else as one '_', none at the ends (so
// never "__", which C++ reserves); "s_" in front of a leading digit, "s" for nothing.
std::string c_identifier(std::string_view text);

struct IghNames {
    std::string network;
    std::vector<std::string> slave;                                    // by position
    std::map<std::pair<std::size_t, std::size_t>, std::string> entry;  // (position, entry number in SM order) -> offset variable
    std::map<std::pair<std::size_t, std::size_t>, bool> bit_entry;     // the entry needs a bit position too
};

// Only an entry IgH can register gets a variable: not padding, and the first of a repeated
// index:sub-index in the slave (IgH finds an entry by index and sub-index).
IghNames igh_names(const Network& network);

}  // namespace esi::net
