#pragma once
// What a description says of its ESC's resources (Info/EtherCATController: DpramSize, SmCount,
// FmmuCount; ESC registers 0x0006, 0x0005, 0x0004), bounded by what the register map has room for.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "esi/check/rule.hpp"
#include "esi/model/device.hpp"

namespace esi::rules {

// The register map has room for 16 SyncManagers (0x0800 + 8n up to 0x087F) and 16 FMMUs (0x0600 +
// 16n up to 0x06FF; ESC datasheet section II).
constexpr std::uint64_t register_map_blocks = 16;

struct BlockLimit {
    std::uint64_t count;
    bool stated = false;  // Info/EtherCATController/<element> gives the count, not the register map
};

// How many register blocks of a kind the ESC has: Info/EtherCATController/<element> (SmCount,
// FmmuCount) where given and readable, else the register map's 16.
[[nodiscard]] BlockLimit block_limit(const Device& device, std::string_view element);
// For a message: where the count comes from. `what` names the blocks.
[[nodiscard]] std::string block_limit_reason(const BlockLimit& limit, std::string_view element, std::string_view what);

// Reports the first of `blocks` (a device's Sm or Fmmu elements) past what the ESC has (sm-count,
// fmmu-count): `element` is the EtherCATController count, `what` names the blocks in the message
// ("SyncManagers"), `prefix` numbers them ("SM").
template <typename Block>
void report_blocks_past_limit(const Device& device, const std::vector<Block>& blocks, std::string_view element, std::string_view what,
                              std::string_view prefix, RuleContext& context) {
    const BlockLimit limit = block_limit(device, element);
    if (blocks.size() <= limit.count) return;
    context.report(blocks[limit.count].pos, "the device describes " + std::to_string(blocks.size()) + " " + std::string(what) + ", " +
                                                std::string(prefix) + std::to_string(limit.count) +
                                                " and above are more than the ESC has (" + block_limit_reason(limit, element, what) +
                                                "); the master cannot configure them");
}

}  // namespace esi::rules
