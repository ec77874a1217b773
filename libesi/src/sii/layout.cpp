#include "esi/sii/layout.hpp"

namespace esi::sii {

std::string_view category_name(std::uint16_t type) {
    switch (type) {
        case category::nop: return "NOP";
        case category::strings: return "Strings";
        case category::data_types: return "DataTypes";
        case category::general: return "General";
        case category::fmmu: return "FMMU";
        case category::sync_manager: return "SyncM";
        case category::fmmu_ex: return "FMMU_EX";
        case category::sync_unit: return "SyncUnit";
        case category::tx_pdo: return "TxPDO";
        case category::rx_pdo: return "RxPDO";
        case category::dc: return "DC";
        case category::timeouts: return "Timeouts";
        case category::dictionary: return "Dictionary";
        case category::hardware: return "Hardware";
        case category::vendor_information: return "VendorInformation";
        case category::images: return "Images";
        case category::end: return "End";
        default: break;
    }
    if (type >= 1 && type <= 9) return "device specific";
    if (type >= 0x0800 && type <= 0x1FFF) return "vendor specific";
    if (type >= 0x2000 && type <= 0x2FFF) return "application specific";
    if (type >= 0x3000 && type <= 0xFFFE) return "vendor specific";
    return "reserved";
}

}  // namespace esi::sii
