#pragma once
// The process data of a device or module as the pictures draw it: the fields of one PDO, and the
// default process image of each SyncManager (the PDOs with an Sm attribute, ETG.2000 PdoType@Sm,
// laid end to end in the order the file lists them, as a master assigns them by default).

#include <cstdint>
#include <string>
#include <vector>

#include "esi/doc/bit_layout.hpp"
#include "esi/model/device.hpp"

namespace esi::doc {

// The entries of `pdo` from bit 0, named in language `lcid`; every field gets `group`.
[[nodiscard]] std::vector<LayoutField> pdo_fields(const Pdo& pdo, std::uint32_t lcid, std::uint32_t group = 0);

// "0x6000:01" for a mapped entry, "" for padding.
[[nodiscard]] std::string entry_address(const PdoEntry& entry);

struct SmImage {
    std::uint32_t sm = 0;             // SyncManager number (position in the device)
    std::vector<const Pdo*> pdos;     // assigned by default, in file order
    std::vector<LayoutField> fields;  // every entry at its offset in the SM; group = position in `pdos`
    std::uint64_t bit_size = 0;
};

// One image per SyncManager that has PDOs assigned by default, in SM order. PDOs whose Sm names
// no SyncManager of the device still get an image (under that number), so no entry goes unseen.
[[nodiscard]] std::vector<SmImage> sm_images(const Device& device, std::uint32_t lcid);

}  // namespace esi::doc
