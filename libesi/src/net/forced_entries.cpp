// `force_entries:` of a slave: entries whose ESI PdoMapping flag forbids the PDO direction but
// that the user knows the firmware maps (an EC-Engineer export maps an Elmo drive's 0x60FE:00,
// which its ESI marks not mappable). pdo_entries.cpp then accepts them with a warning.

#include <set>

#include "ros2_interfaces_spec.hpp"

namespace esi::net {

std::vector<ForcedEntry> read_forced_entries(yaml::Reader& reader, const yaml::Node& node) {
    std::vector<ForcedEntry> out;
    const auto items = reader.sequence(node, "force_entries");
    if (!items) return out;
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (const yaml::Node& item : *items) {
        const auto text = reader.text(item, "force_entries");
        if (!text) continue;
        ForcedEntry e;
        e.pos = item.pos();
        if (!parse_entry_key(*text, e.index, e.subindex)) {
            reader.error(item, "yaml-type", "a forced entry is INDEX:SUBINDEX (e.g. 0x60FE:0x00), not '" + *text + "'");
            continue;
        }
        if (!seen.insert({e.index, e.subindex}).second) {
            reader.error(item, "yaml-duplicate-key", "entry " + *text + " is listed twice");
            continue;
        }
        out.push_back(e);
    }
    return out;
}

}  // namespace esi::net
