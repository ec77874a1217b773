#pragma once
// The pieces of the code-generation view (docs/codegen.md). Each builder reads the model only and
// returns a view value in the arena it is given; problems that make a piece incomplete come back
// as warnings, never exceptions.

#include <string>

#include "esi/codegen/view_tree.hpp"
#include "esi/data_types.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::codegen {

// Where diagnostics point, and where the view lives.
struct ViewContext {
    std::string path;
    Diagnostics* diagnostics = nullptr;
    ViewArena* arena = nullptr;
    void warn(std::string rule, std::string message, SourcePos pos) const;
};

// The device's object dictionary: objects sorted by index, their entries by sub-index.
struct ObjectsView {
    ViewValue objects;  // a list
    std::size_t entry_count = 0;
    bool soes_storage = false;  // some object has a member in SOES's Obj
};
[[nodiscard]] ObjectsView objects_view(const Device& device, const ViewContext& context);

// RxPdo or TxPdo elements with entries, bit offsets and mapping values.
[[nodiscard]] ViewValue pdos_view(const Device& device, PdoDirection direction, const ViewContext& context);

// The default process image of one direction: the PDOs with an Sm attribute, as a packed struct.
[[nodiscard]] ViewValue process_image_view(const Device& device, PdoDirection direction, const ViewContext& context);

// Everything about one device; `c_name` is unique among the devices of the view.
[[nodiscard]] ViewValue device_view(const EtherCATInfo& info, const Device& device, const std::string& c_name,
                               const std::string& symbol_prefix, const ViewContext& context);

// The C type that holds one value of a basic type of `bit_size` bits: "uint16_t", "float", or an
// array ("char" / "uint8_t" with a length) for strings, octets, structures and sizes above 64 bits.
struct CType {
    std::string_view type;  // a literal
    std::uint64_t array_length = 0;  // 0: scalar
};
[[nodiscard]] CType c_type_of(const BasicType* basic, std::uint64_t bit_size);

// The basic type a PDO entry carries: its DataType, else the mapped object's entry type.
[[nodiscard]] const BasicType* pdo_entry_basic_type(const PdoEntry& entry, const Dictionary* dictionary);

// What an entry's ObjectFlags allow: written over SDO (Access rw or wo; an absent Access reads
// as ro), and mapped into RxPDOs (PdoMapping has R) or TxPDOs (T).
struct EntryAccess {
    bool writable = false;
    bool rx_mappable = false;
    bool tx_mappable = false;
};
[[nodiscard]] EntryAccess entry_access(const ObjectFlags* flags);

// SOES's limits of one direction's process data (ecat_options.h: MAX_MAPPINGS_SM2/3,
// MAX_RXPDO_SIZE/MAX_TXPDO_SIZE) for the largest assignment and mapping the object dictionary
// lets a master write; soes_view.cpp explains the bound.
struct SoesPdoLimits {
    std::uint64_t max_mappings = 1;  // mapping entries SOES keeps (SMmap2/SMmap3), padding included
    std::uint64_t max_bytes = 8;     // the rxpdo/txpdo buffer, whole 64-bit words
    bool remappable = false;         // the master may write the assignment or a mapping
    std::uint64_t max_entry_bits = 0;  // the largest BitLen a mapping entry may have
};
[[nodiscard]] SoesPdoLimits soes_pdo_limits(const Device& device, PdoDirection direction);
[[nodiscard]] ViewValue soes_view(const Device& device, bool has_storage, ViewArena& arena);

// Vendor Id and name.
[[nodiscard]] ViewValue vendor_view(const EtherCATInfo& info, ViewArena& arena);

}  // namespace esi::codegen
