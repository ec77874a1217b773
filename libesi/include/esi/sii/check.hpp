#pragma once
// ESI device vs SII image, the way the ETG conformance tool's ESI test file (TF-1300, as
// publicly posted in leducp/KickCAT PR #181) compares them: 2-1/2-2/2-3 vendor id, product
// code, revision; 2-5 mailbox protocols; 2-6 EEPROM size; 2-8 ConfigData; 2-10 General
// category; 1-3 port types; 2-11 FMMU and 2-12 SyncM categories; plus the standard and
// bootstrap mailbox words, and the PDO and DC categories where the image has them.
//
// Every mismatch is a diagnostic on the ESI element (path = ESI file, line/column) with a note
// naming the image byte offset. Values are compared through the same mapping the builder uses
// (mapping.hpp), so an image built from an ESI always checks clean against it.

#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/sii/decode.hpp"

namespace esi::sii {

[[nodiscard]] Diagnostics check_image(const EtherCATInfo& info, const Device& device, const DecodedImage& image,
                                      const std::string& esi_path, const std::string& image_path);

// The device of an ESI document that an image describes: the exact product code and revision;
// else the same product code (the highest revision); else the only device of the document.
struct ImageDevice {
    const EtherCATInfo* info = nullptr;
    const Device* device = nullptr;
    bool exact = false;
};
[[nodiscard]] ImageDevice find_device_for_image(const EsiDocument& document, const Header& header);

}  // namespace esi::sii
