#pragma once
// Device resolution: which indexed device a network's slave (or `esi-net find`) means.
//
// A slave names its device by Type text (`device: EL1008`) or by product code with an optional
// revision and vendor id. Without a revision, the highest one found is used, with a note. A name
// that several products carry is ambiguous: the error lists the candidates. When nothing
// matches, the error names the nearest identities (the same product code at other revisions,
// names close to the one written) and where it looked.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/net/library_index.hpp"

namespace esi::net {

struct DeviceQuery {
    std::optional<std::string> name;  // Type text
    std::optional<std::uint32_t> vendor_id;
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision_no;
};

// "0x00000002 0x044C2C52 rev 0x00120000 EK1100" style, for messages.
[[nodiscard]] std::string describe_identity(const IndexedDevice& device);
[[nodiscard]] std::string describe_query(const DeviceQuery& query);

struct Resolution {
    const IndexedDevice* device = nullptr;  // null when not resolved (an error says why)
    // The same identity (vendor, product code, revision) in other files, in the order the
    // roots were given; `device` is the first of them in that order.
    std::vector<const IndexedDevice*> duplicates;
    Diagnostics diagnostics;                // the error, or notes on the choice made
};

// `path` and `pos` locate the request (the slave in NETWORK.yaml) in the diagnostics.
[[nodiscard]] Resolution resolve_device(const LibraryIndex& index, const DeviceQuery& query, const std::string& path,
                                        SourcePos pos);

// `esi-net find`: every device matching the query (all revisions when none is given), in
// index order; an empty result comes with the nearest identities as notes of an error.
struct FindResult {
    std::vector<const IndexedDevice*> devices;
    Diagnostics diagnostics;
};
[[nodiscard]] FindResult find_devices(const LibraryIndex& index, const DeviceQuery& query);

// VENDOR:PRODUCT[:REVISION] (numbers: decimal, 0x… or #x…), a lone PRODUCT number, or a name.
// nullopt and a message when it has colons but is not numbers.
[[nodiscard]] std::optional<DeviceQuery> parse_find_query(std::string_view text, std::string& error);

}  // namespace esi::net
