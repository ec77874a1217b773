#pragma once
// Device -> SII image (ETG.1000.6, ETG.2010; every choice where public tools disagree is in
// docs/sii.md). What does not fit is a diagnostic, never a silent truncation: more than 255
// strings, a string over 255 bytes, more than 255 entries in a PDO, a value too wide for its
// field. An image larger than Eeprom/ByteSize leaves out optional content in a fixed order, with
// a note naming it, and is an error only when the mandatory part does not fit (or with
// fit_to_eeprom off). An error means the image must not be written; the bytes are still returned
// so callers can inspect them.

#include <cstdint>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/model/language.hpp"
#include "esi/sii/image.hpp"

namespace esi::sii {

struct BuildOptions {
    bool include_pdos = true;  // TxPDO/RxPDO categories (esi-sii --no-pdo)
    bool include_dc = true;    // DC category (esi-sii --no-dc)
    // Language of the names written as strings: this LcId when the ESI has it, else the usual
    // primary name (English, else the name without LcId, else the first). Beckhoff's own
    // images carry the German (1031) names.
    std::uint32_t name_lcid = default_lcid;
    // Fill the image with 0xFF (erased EEPROM) up to the EEPROM size, as every tool that wrote
    // the corpus images does.
    bool pad_to_eeprom_size = true;
    // An image larger than Eeprom/ByteSize leaves out optional content until it fits, the way
    // vendor tools make images (docs/sii.md §1, "Images larger than the EEPROM"); false refuses
    // it instead (esi-sii build --strict-size).
    bool fit_to_eeprom = true;
    // A device without Eeprom/ConfigData gets PDI control 0 (the PDI off): a warning, or with
    // this an error (esi-gen --strict). docs/sii.md §2.
    bool refuse_pdi_off = false;
};

// Optional content a build left out so that the image fits its EEPROM; all false is the whole
// image. --no-pdo and --no-dc are options, not omissions.
struct Omissions {
    bool pdos = false;             // the TxPDO and RxPDO categories
    bool unassigned_pdos = false;  // the PDOs without @Sm (not in the default assignment)
    bool dc = false;               // the DC category
    bool dc_descriptions = false;  // the description strings of the DC op modes
    bool group_string = false;     // the General category's group name (GroupType)
    bool order_string = false;     // the General category's order number (Type)
    bool name_string = false;      // the General category's device name

    [[nodiscard]] bool any() const {
        return pdos || unassigned_pdos || dc || dc_descriptions || group_string || order_string || name_string;
    }
};

struct BuildResult {
    std::vector<std::uint8_t> bytes;  // the image; padded to the EEPROM size unless told not to
    Image image;                      // what the bytes hold
    bool from_eeprom_data = false;    // Eeprom/Data was used as it is
    std::size_t content_bytes = 0;    // header + categories + end marker, before padding
    std::uint64_t eeprom_bytes = 0;   // the EEPROM size the image declares in word 0x3E
    Omissions omitted;                  // what was left out so that the image fits
    std::vector<std::string> left_out;  // the same for people, in the order it was left out
    Diagnostics diagnostics;          // path: the ESI (or YAML) the device came from

    [[nodiscard]] bool ok() const { return !diagnostics.has_errors(); }
};

// `info` supplies Vendor/Id and the groups; `device` must be one of info.devices (or a device
// built for it). `path` is used in diagnostics.
[[nodiscard]] BuildResult build_image(const EtherCATInfo& info, const Device& device, const BuildOptions& options = {},
                                      const std::string& path = {});

}  // namespace esi::sii
