#pragma once
// A pass over the YAML event stream before any node tree is walked. It enforces what the node
// API cannot see or would make expensive:
//  - nesting depth (a deep flow sequence would otherwise recurse through every later walk);
//  - the size of the document after anchor/alias expansion: yaml-cpp shares an aliased node
//    instead of copying it, so a "billion laughs" file parses in linear time but any walk over
//    it visits 10^9 nodes. The scan adds, at every alias, the node count of the anchored
//    subtree and stops at the first alias that crosses the limit;
//  - duplicate mapping keys, which yaml-cpp keeps silently (the first one wins on lookup);
//  - exactly one document per file.
// Every finding carries the YAML position (yaml-cpp marks are 0-based; ours are 1-based).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "esi/diagnostic.hpp"

namespace esi::yaml {

struct PrescanLimits {
    std::size_t max_depth = 64;
    std::uint64_t max_nodes = 1'000'000;  // after alias expansion
};

struct PrescanResult {
    bool ok = false;  // false: the tree must not be walked (diagnostics say why); duplicate keys leave it walkable
    std::uint64_t expanded_nodes = 0;
    bool empty = false;  // no document at all
};

// `text` must already be within the input size limit.
[[nodiscard]] PrescanResult prescan(std::string_view text, const std::string& path, const PrescanLimits& limits,
                                    Diagnostics& diagnostics);

}  // namespace esi::yaml
