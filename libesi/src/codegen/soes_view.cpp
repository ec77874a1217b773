// The SOES process-data limits of a device (docs/codegen.md, "SOES"): how many mapping entries
// SOES must be able to hold per SyncManager and how large its rxpdo/txpdo buffers must be.
//
// SOES computes the process image at PreOp->SafeOp from the objects themselves (soes/esc_coe.c
// sizeOfPDO): for each PDO listed in 0x1C12 (outputs) or 0x1C13 (inputs) it walks the mapping
// object's entries, adds each entry's BitLen to the image and keeps one SMmap slot per entry,
// padding included. It refuses the state change when the slots run out, and copies ESC_SM2_sml
// bytes into rxpdo[MAX_RXPDO_SIZE] without comparing the two (soes/ecat_slv.c RXPDO_update). So
// the limits must cover every assignment and mapping a master may write, not only the default:
//   - a writable assignment object may name, in each of its sub-entries, any mapping object of
//     its direction (SOES does not reject a PDO assigned twice);
//   - a writable mapping object may hold as many entries as it has sub-entries, each at most as
//     long as the longest entry of the dictionary that can be mapped in that direction (padding
//     entries included: a gap longer than that is not a mapping the dictionary allows);
//   - read-only objects hold their defaults.
// SOES packs and unpacks the buffers a 64-bit word at a time (esc_coe.c COE_bitsliceGet/Set read
// and write the whole words an entry touches), so a buffer is a whole number of 8-byte words: a
// 1-byte image in a 5-byte buffer is a read past its end. With MAX_MAPPINGS_SMx 0 SOES expects
// the application to supply the buffer itself (ecat_slv.c: `extern uint8_t rxpdo[]`), so the
// limits are at least one mapping and one word.

#include <algorithm>
#include <map>

#include "codegen/values.hpp"
#include "codegen/view_parts.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::codegen {

namespace {

struct MappingSize {
    std::uint64_t entries = 0;
    std::uint64_t bits = 0;
};

bool in_mapping_range(std::uint32_t index, PdoDirection direction) {
    return direction == PdoDirection::rx ? index >= 0x1600 && index <= 0x17FF : index >= 0x1A00 && index <= 0x1BFF;
}

std::optional<std::uint64_t> default_of(const ObjectEntry& entry) {
    const DecodedValue v = decode_entry_values(entry).default_value;
    if (v.kind != DecodedValue::Kind::unsigned_integer && v.kind != DecodedValue::Kind::signed_integer) return std::nullopt;
    return v.bits;
}

// The sub-entries 1..n of an ARRAY/RECORD (the mapping or assignment slots).
std::vector<const ObjectEntry*> slots_of(const ObjectLayout& layout) {
    std::vector<const ObjectEntry*> out;
    for (const auto& e : layout.entries)
        if (e.subindex >= 1 && e.subindex <= 255) out.push_back(&e);
    return out;
}

bool any_writable(const ObjectLayout& layout) {
    return std::any_of(layout.entries.begin(), layout.entries.end(), [](const ObjectEntry& e) { return entry_access(e.flags).writable; });
}

// The slots in use by default: sub-index 0's default when it is a count, else all of them.
std::vector<const ObjectEntry*> default_slots(const ObjectLayout& layout) {
    std::vector<const ObjectEntry*> slots = slots_of(layout);
    if (const ObjectEntry* count = layout.entry(0))
        if (const auto n = default_of(*count); n && *n < slots.size()) slots.resize(static_cast<std::size_t>(*n));
    return slots;
}

}  // namespace

SoesPdoLimits soes_pdo_limits(const Device& device, PdoDirection direction) {
    const Dictionary* dictionary = device.dictionary();
    const bool rx = direction == PdoDirection::rx;
    SoesPdoLimits limits;

    // The longest entry a mapping of this direction may carry.
    std::uint64_t longest = 0;
    for (const Pdo& pdo : device.pdos(direction))
        for (const PdoEntry& e : pdo.entries) longest = std::max<std::uint64_t>(longest, e.bit_len);
    std::map<std::uint32_t, ObjectLayout> layouts;
    if (dictionary) {
        const DataTypeIndex types(dictionary);
        for (const Object& object : dictionary->objects) {
            if (object.index > 0xFFFF || layouts.count(object.index)) continue;
            ObjectLayout layout = layout_of(types, object);
            for (const auto& e : layout.entries) {
                const EntryAccess a = entry_access(e.flags);
                if (rx ? a.rx_mappable : a.tx_mappable) longest = std::max(longest, e.bit_size);
            }
            layouts.emplace(object.index, std::move(layout));
        }
    }
    limits.max_entry_bits = longest;

    // Each mapping object: the PDO element gives the default; the dictionary object, when it is
    // writable, the most it can hold.
    std::map<std::uint32_t, MappingSize> mappings;
    for (const Pdo& pdo : device.pdos(direction)) mappings[pdo.index] = {pdo.entries.size(), pdo.bit_size()};
    for (const auto& [index, layout] : layouts) {
        if (!in_mapping_range(index, direction)) continue;
        if (any_writable(layout)) {
            const std::uint64_t n = slots_of(layout).size();
            mappings[index] = {n, n * longest};
            limits.remappable = true;
        } else if (!mappings.count(index)) {
            MappingSize fixed;
            for (const ObjectEntry* slot : default_slots(layout)) {
                ++fixed.entries;
                fixed.bits += default_of(*slot).value_or(0) & 0xFF;  // a mapping value's low byte is its BitLen
            }
            mappings[index] = fixed;
        }
    }

    MappingSize total;
    const auto assignment = layouts.find(rx ? 0x1C12 : 0x1C13);
    if (assignment != layouts.end() && any_writable(assignment->second)) {
        MappingSize largest;
        for (const auto& [index, size] : mappings) {
            largest.entries = std::max(largest.entries, size.entries);
            largest.bits = std::max(largest.bits, size.bits);
        }
        const std::uint64_t n = slots_of(assignment->second).size();
        total = {n * largest.entries, n * largest.bits};
        limits.remappable = true;
    } else if (assignment != layouts.end()) {
        for (const ObjectEntry* slot : default_slots(assignment->second)) {
            const auto index = default_of(*slot);
            if (!index) continue;
            const auto it = mappings.find(static_cast<std::uint32_t>(*index));
            if (it == mappings.end()) continue;
            total.entries += it->second.entries;
            total.bits += it->second.bits;
        }
    } else {
        // No assignment object in the dictionary: SOES maps nothing itself and the application
        // assigns the PDOs; any of them may be in use.
        for (const auto& [index, size] : mappings) {
            total.entries += size.entries;
            total.bits += size.bits;
        }
    }
    limits.max_mappings = std::max<std::uint64_t>(1, total.entries);
    limits.max_bytes = std::max<std::uint64_t>(1, (total.bits + 63) / 64) * 8;
    return limits;
}

ViewValue soes_view(const Device& device, bool has_storage, ViewArena& arena) {
    ObjectBuilder soes(arena);
    soes.add("has_storage", has_storage);
    for (const PdoDirection direction : {PdoDirection::rx, PdoDirection::tx}) {
        const SoesPdoLimits limits = soes_pdo_limits(device, direction);
        ObjectBuilder d(arena);
        d.add("max_mappings", limits.max_mappings);
        d.add("max_bytes", limits.max_bytes);
        d.add("remappable", limits.remappable);
        d.add("max_entry_bits", limits.max_entry_bits);
        if (direction == PdoDirection::rx) soes.add("rx", d.finish());
        else soes.add("tx", d.finish());
    }
    return soes.finish();
}

}  // namespace esi::codegen
