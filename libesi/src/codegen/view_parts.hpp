#pragma once
// The pieces of the code-generation view (docs/codegen.md). Each builder reads the model only and
// returns a view value in the arena it is given; problems that make a piece incomplete come back
// as warnings, never exceptions.

#include <string>

#include "codegen/view_tree.hpp"
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

// Vendor Id and name.
[[nodiscard]] ViewValue vendor_view(const EtherCATInfo& info, ViewArena& arena);

}  // namespace esi::codegen
