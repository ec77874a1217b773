#pragma once
// Eeprom element: either a raw image (Data) or the structured ByteSize/ConfigData/BootStrap form.

#include "esi/model/common.hpp"

namespace esi {

struct EepromCategory {
    std::uint32_t cat_no = 0;
    SourcePos cat_no_pos;
    std::optional<HexData> data;
    std::optional<std::string> data_string;
    std::optional<std::uint64_t> data_uint;
    std::optional<std::uint64_t> data_udint;
    std::optional<bool> preserve_online_data;
    SourcePos pos;
    Extras extras;
};

struct Eeprom {
    std::optional<HexData> data;  // complete image, used as it is
    std::optional<std::uint32_t> byte_size;
    SourcePos byte_size_pos;
    std::optional<HexData> config_data;  // SII words 0..6 (or a prefix)
    std::optional<HexData> boot_strap;   // 8 bytes: boot mailbox out offset/size, in offset/size
    std::vector<EepromCategory> categories;
    std::optional<bool> assign_to_pdi;
    SourcePos pos;
    Extras extras;
};

}  // namespace esi
