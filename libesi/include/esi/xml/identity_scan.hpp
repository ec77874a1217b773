#pragma once
// The identities of the devices an ESI file describes, found without building the model.
//
// A library index (esi-net) visits every file of an ESI library, hundreds of MB, to learn which
// file describes which device; only the file it then picks is read whole (read_esi). The scan
// tokenises the markup (comments, CDATA sections, processing instructions, quoted attribute
// values), reads Vendor/Id and Name and each Device's Type, HideType and Name, and skips the rest of a Device's
// content once its leading elements are read. It builds no element tree.
//
// Invariant (tested over the corpus): for a file read_esi accepts, the scan lists the same
// devices in the same order, with the same product code, revision number, Type text and
// vendor id as the model.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/source_pos.hpp"

namespace esi {

// A HideType of a Device: a revision (of its own product code unless one is given) that the
// vendor's catalogue shows this device in place of.
struct HiddenIdentity {
    std::optional<std::uint32_t> product_code;  // the Device's own when the HideType names none
    std::optional<std::uint32_t> revision_no;
    bool operator==(const HiddenIdentity&) const = default;
};

struct ScannedDevice {
    std::optional<std::uint32_t> vendor_id;  // Vendor/Id of the EtherCATInfo that holds the device
    std::string vendor_name;                 // its Vendor/Name (LcId 1033, else the first), trimmed
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision_no;
    std::string type;         // Type text, trimmed
    std::string name;         // the Name with LcId 1033, else the first Name; trimmed
    std::size_t offset = 0;   // byte offset of "<Device" in the file as UTF-8
    SourcePos pos;            // its line and column
    std::size_t ordinal = 0;  // place among the file's devices, in document order
    std::vector<HiddenIdentity> hides;  // its HideType elements, in document order
};

struct IdentityScan {
    std::vector<ScannedDevice> devices;
    // Empty when the markup could be tokenised; else why not (the caller reads the file with
    // read_esi to get a located error).
    std::string error;
    [[nodiscard]] bool ok() const { return error.empty(); }
};

// `bytes` as read from the file (any encoding read_esi accepts).
[[nodiscard]] IdentityScan scan_identities(std::string bytes);

}  // namespace esi
