#pragma once
// The pieces of the code-generation view (docs/codegen.md). Each builder reads the model only and
// returns JSON; problems that make a piece incomplete come back as warnings, never exceptions.

#include <string>

#include <nlohmann/json.hpp>

#include "esi/data_types.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::codegen {

using Json = nlohmann::ordered_json;

// Where diagnostics point.
struct ViewContext {
    std::string path;
    Diagnostics* diagnostics = nullptr;
    void warn(std::string rule, std::string message, SourcePos pos) const;
};

// The device's object dictionary: objects sorted by index, their entries by sub-index.
struct ObjectsView {
    Json objects = Json::array();
    std::size_t entry_count = 0;
};
[[nodiscard]] ObjectsView objects_view(const Device& device, const ViewContext& context);

// RxPdo or TxPdo elements with entries, bit offsets and mapping values.
[[nodiscard]] Json pdos_view(const Device& device, PdoDirection direction);

// The default process image of one direction: the PDOs with an Sm attribute, as a packed struct.
[[nodiscard]] Json process_image_view(const Device& device, PdoDirection direction, const ViewContext& context);

// Everything about one device; `c_name` is unique among the devices of the view.
[[nodiscard]] Json device_view(const EtherCATInfo& info, const Device& device, const std::string& c_name,
                               const std::string& symbol_prefix, const ViewContext& context);

// The C type that holds one value of a basic type of `bit_size` bits: "uint16_t", "float", or an
// array ("char" / "uint8_t" with a length) for strings, octets, structures and sizes above 64 bits.
struct CType {
    std::string type;
    std::uint64_t array_length = 0;  // 0: scalar
};
[[nodiscard]] CType c_type_of(const BasicType* basic, std::uint64_t bit_size);

// The basic type a PDO entry carries: its DataType, else the mapped object's entry type.
[[nodiscard]] const BasicType* pdo_entry_basic_type(const PdoEntry& entry, const Dictionary* dictionary);

// Vendor Id and name.
[[nodiscard]] Json vendor_view(const EtherCATInfo& info);

}  // namespace esi::codegen
