// The entries of configurable PDOs (NETWORK.yaml `pdo_entries`), as TwinCAT and EC-Engineer let
// integrators edit a PDO that is not Fixed when the device allows PDO configuration
// (ETG.2000 CoE@PdoConfig). Each entry is checked against the object dictionary: the object
// and sub-index exist, the bit length is the entry's size, and the entry may be mapped in that
// direction (Flags/PdoMapping R or T, or the ESI maps it in a PDO of that direction already);
// and against the device family's limits (entries per PDO, allowed bit lengths).

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

#include "esi/model/object_layout.hpp"
#include "slave_context.hpp"

namespace esi::net {

namespace {

bool flag_allows(const ObjectFlags* flags, PdoDirection direction) {
    if (!flags || !flags->pdo_mapping) return false;
    const char wanted = direction == PdoDirection::rx ? 'R' : 'T';
    return std::any_of(flags->pdo_mapping->begin(), flags->pdo_mapping->end(),
                       [&](char ch) { return std::toupper(static_cast<unsigned char>(ch)) == wanted; });
}

bool mapped_by_esi(const Device& device, PdoDirection direction, std::uint32_t index, std::uint32_t subindex) {
    for (const Pdo& p : device.pdos(direction))
        for (const PdoEntry& e : p.entries)
            if (e.index == index && e.effective_subindex() == subindex) return true;
    return false;
}

std::string subindex_list(const ObjectLayout& layout) {
    std::string out;
    for (const ObjectEntry& e : layout.entries) out += (out.empty() ? "" : ", ") + fmt::format("{:02X}", e.subindex);
    return out;
}

bool restates_entries(const ConfiguredPdo& pdo, const PdoEntriesSpec& spec) {
    if (pdo.entries.size() != spec.entries.size()) return false;
    for (std::size_t i = 0; i < spec.entries.size(); ++i) {
        const ConfiguredEntry& have = pdo.entries[i];
        const PdoEntrySpec& want = spec.entries[i];
        if (have.index != want.index || have.bit_len != want.bit_len || (want.index != 0 && have.subindex != want.subindex)) return false;
    }
    return true;
}

}  // namespace

void configure_pdo_entries(SlaveContext& c) {
    const bool dictionary = has_dictionary(c);
    for (const PdoEntriesSpec& spec : c.spec.pdo_entries) {
        auto it = std::find_if(c.slave.pdos.begin(), c.slave.pdos.end(), [&](const ConfiguredPdo& p) { return p.index == spec.pdo; });
        if (it == c.slave.pdos.end()) {
            c.error(spec.pos, "net-pdo-entries",
                    fmt::format("PDO {} is not assigned; give its entries only for a PDO in 'pdos' (or the default assignment)",
                                hex_index(spec.pdo)));
            continue;
        }
        ConfiguredPdo& pdo = *it;
        if (pdo.fixed) {
            // Restating a Fixed PDO's entries exactly as the ESI declares them is no change (an
            // ENI or a network written from one lists every assigned PDO's entries).
            if (restates_entries(pdo, spec)) continue;
            c.error(spec.pos, "net-pdo-fixed", fmt::format("PDO {} is Fixed in the ESI; its entries cannot be changed", hex_index(spec.pdo)));
            continue;
        }
        if (!c.coe() || !c.device.mailbox->coe->pdo_config.value_or(false)) {
            c.error(spec.pos, "net-pdo-config",
                    c.device.type.text + " does not allow PDO configuration (no CoE PdoConfig in the ESI)");
            continue;
        }
        if (c.limits.max_entries_per_pdo && spec.entries.size() > *c.limits.max_entries_per_pdo)
            c.error(spec.pos, "net-limit-entries",
                    fmt::format("{} entries in {}; the device maps at most {} per PDO (limits)", spec.entries.size(), hex_index(spec.pdo),
                                *c.limits.max_entries_per_pdo));
        if (!dictionary)
            c.warning(spec.pos, "net-pdo-entries-unchecked",
                      fmt::format("the ESI of {} has no object dictionary; the entries of {} are taken as written", c.device.type.text,
                                  hex_index(spec.pdo)));
        std::vector<ConfiguredEntry> entries;
        bool ok = true;
        for (const PdoEntrySpec& e : spec.entries) {
            ConfiguredEntry ce;
            ce.index = e.index;
            ce.subindex = e.index == 0 ? 0 : e.subindex;
            ce.bit_len = e.bit_len;
            if (e.index == 0) {
                entries.push_back(std::move(ce));
                continue;
            }
            const std::string where = fmt::format("{}:{:02X}", hex_index(e.index), e.subindex);
            if (!c.limits.allowed_bit_lens.empty() &&
                std::find(c.limits.allowed_bit_lens.begin(), c.limits.allowed_bit_lens.end(), e.bit_len) == c.limits.allowed_bit_lens.end()) {
                c.error(e.pos, "net-limit-bitlen", fmt::format("{}: {} bits is not a bit length the device maps (limits)", where, e.bit_len));
                ok = false;
            }
            if (!dictionary) {
                ce.name = where;
                entries.push_back(std::move(ce));
                continue;
            }
            const FoundObject found = find_object(c, e.index);
            const Object* object = found.object;
            if (!object) {
                c.error(e.pos, "net-entry-unknown", fmt::format("{} is not in the object dictionary of {}", hex_index(e.index), c.device.type.text));
                ok = false;
                continue;
            }
            const ObjectLayout layout = layout_of(found.dictionary, *object);
            const ObjectEntry* entry = layout.entry(e.subindex);
            if (!entry) {
                c.error(e.pos, "net-entry-unknown",
                        fmt::format("{} ({}) has no sub-index {:02X}; it has {}", hex_index(e.index), primary_text(object->names), e.subindex,
                                    subindex_list(layout)));
                ok = false;
                continue;
            }
            if (entry->bit_size != e.bit_len) {
                c.error(e.pos, "net-entry-size", fmt::format("{} ({}) is {} bits, not {}", where, entry->name, entry->bit_size, e.bit_len));
                ok = false;
            }
            if (!flag_allows(entry->flags, pdo.direction) && !mapped_by_esi(c.device, pdo.direction, e.index, e.subindex)) {
                const std::string flag = entry->flags && entry->flags->pdo_mapping ? *entry->flags->pdo_mapping : std::string("none");
                const char* into = pdo.direction == PdoDirection::rx ? "n RxPDO" : " TxPDO";
                const auto forced = std::find_if(c.spec.force_entries.begin(), c.spec.force_entries.end(),
                                                 [&](const ForcedEntry& f) { return f.index == e.index && f.subindex == e.subindex; });
                if (forced != c.spec.force_entries.end()) {
                    c.warning(e.pos, "net-entry-forced",
                              fmt::format("{} ({}) is mapped into a{} although its PdoMapping flag is '{}' (force_entries): the device "
                                          "refuses the mapping unless its firmware allows it",
                                          where, entry->name, into, flag));
                } else {
                    Diagnostic& d = c.error(e.pos, "net-entry-not-mappable",
                                            fmt::format("{} ({}) cannot be mapped into a{} (its PdoMapping flag is '{}')", where, entry->name, into, flag));
                    d.notes.push_back({c.network.path, e.pos,
                                       fmt::format("if the device's firmware maps it anyway, list it under the slave's force_entries: [{}:{:02X}]",
                                                   hex_index(e.index), e.subindex)});
                    ok = false;
                }
            }
            ce.name = layout.code == ObjectCode::var ? primary_text(object->names) : entry->name;
            ce.data_type = entry->type;
            entries.push_back(std::move(ce));
        }
        if (ok) {
            pdo.entries = std::move(entries);
            pdo.entries_configured = true;
        }
    }
}

}  // namespace esi::net
