#include <algorithm>

#include "esi/model/device.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

std::uint64_t Pdo::bit_size() const {
    std::uint64_t total = 0;
    for (const auto& e : entries) total += e.bit_len;
    return total;
}

std::uint16_t Mailbox::protocol_bits() const {
    std::uint16_t bits = 0;
    if (aoe) bits |= 0x01;
    if (eoe) bits |= 0x02;
    if (coe) bits |= 0x04;
    if (foe) bits |= 0x08;
    if (soe) bits |= 0x10;
    if (voe) bits |= 0x20;
    return bits;
}

const Object* Dictionary::find_object(std::uint32_t index) const {
    for (const auto& o : objects)
        if (o.index == index) return &o;
    return nullptr;
}

const DataType* Dictionary::find_data_type(std::string_view name) const {
    for (const auto& t : data_types)
        if (t.name == name) return &t;
    return nullptr;
}

const Dictionary* Device::dictionary() const {
    for (const auto& p : profiles)
        if (p.dictionary) return &*p.dictionary;
    return nullptr;
}

const Pdo* Device::find_pdo(std::uint32_t index) const {
    for (const auto* list : {&rx_pdos, &tx_pdos})
        for (const auto& p : *list)
            if (p.index == index) return &p;
    return nullptr;
}

const Group* EtherCATInfo::find_group(std::string_view type) const {
    for (const auto& g : groups)
        if (g.type == type) return &g;
    return nullptr;
}

std::string_view root_element_name(DocumentKind kind) {
    switch (kind) {
        case DocumentKind::ethercat_info: return "EtherCATInfo";
        case DocumentKind::ethercat_info_list: return "EtherCATInfoList";
        case DocumentKind::ethercat_module: return "EtherCATModule";
        case DocumentKind::ethercat_dict: return "EtherCATDict";
        case DocumentKind::ethercat_diag: return "EtherCATDiag";
        case DocumentKind::unknown: return "";
    }
    return "";
}

}  // namespace esi
