#pragma once
// `esi-net find`: devices of the library index by identity, by partial name and by vendor,
// ranked.
//
// A name matches a device's Type text (`EL2008`, `InoSV660N`) or its Name (`EK1100 EtherCAT
// Coupler`), ignoring case, and ranks as
//   exact      the Type text is the name;
//   prefix     the Type text starts with it;
//   substring  the Type text or the Name contains it (`SV660` finds `InoSV660N`);
//   fuzzy      the Type text is a few edits away (a typo) — only when nothing of the above
//              matched, so that `EL2008` does not list every EL20x8.
// A vendor (`--vendor Elmo`) keeps the devices whose file's Vendor/Name contains the text, or
// whose vendor id is the number given; alone, it lists every device of that vendor. Identity
// queries (VENDOR:PRODUCT[:REVISION]) match exactly. The order is rank, Type text, current
// before hidden (legacy) revisions, revision (highest first), then the index's order (file path,
// document order): deterministic, and the first line of a name is what `build` would take.

#include <optional>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/net/library_index.hpp"
#include "esi/net/resolve.hpp"

namespace esi::net {

enum class MatchRank { exact, prefix, substring, fuzzy, vendor };

[[nodiscard]] const char* match_rank_name(MatchRank rank);

struct DeviceMatch {
    const IndexedDevice* device = nullptr;
    MatchRank rank = MatchRank::exact;
    // A device of the same vendor that lists this revision as a HideType: a legacy revision,
    // which `build` passes over without `revision:` (resolve.hpp); null when none does.
    const IndexedDevice* hidden_by = nullptr;
};

struct DeviceSearch {
    std::vector<DeviceMatch> matches;
    Diagnostics diagnostics;  // an error with the nearest identities when nothing matched
};

// `query` may be empty (nullopt) when `vendor` is given; `vendor` is a name (part of it) or a
// vendor id (decimal, 0x… or #x…).
[[nodiscard]] DeviceSearch search_devices(const LibraryIndex& index, const std::optional<DeviceQuery>& query,
                                          const std::optional<std::string>& vendor);

// The matches as text lines `file:line:col: identity — Name [rank]` and as JSON.
[[nodiscard]] std::string device_search_text(const LibraryIndex& index, const DeviceSearch& search);
[[nodiscard]] std::string device_search_json(const LibraryIndex& index, const DeviceSearch& search);

}  // namespace esi::net
