#include <algorithm>

#include "esi/model/device.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

std::uint64_t Pdo::bit_size() const {
    std::uint64_t total = 0;
    for (const auto& e : entries) total += e.bit_len;
    return total;
}

bool Mailbox::has(MailboxProtocol protocol) const {
    switch (protocol) {
        case MailboxProtocol::aoe: return aoe.has_value();
        case MailboxProtocol::eoe: return eoe.has_value();
        case MailboxProtocol::coe: return coe.has_value();
        case MailboxProtocol::foe: return foe.has_value();
        case MailboxProtocol::soe: return soe.has_value();
        case MailboxProtocol::voe: return voe.has_value();
    }
    return false;
}

std::uint16_t Mailbox::protocol_bits() const {
    std::uint16_t bits = 0;
    for (const MailboxProtocol protocol : mailbox_protocols)
        if (has(protocol)) bits |= sii_bit(protocol);
    return bits;
}

const std::vector<InitCmd>* Mailbox::init_cmds(MailboxProtocol protocol) const {
    switch (protocol) {
        case MailboxProtocol::aoe: return aoe ? &aoe->init_cmds : nullptr;
        case MailboxProtocol::eoe: return eoe ? &eoe->init_cmds : nullptr;
        case MailboxProtocol::coe: return coe ? &coe->init_cmds : nullptr;
        case MailboxProtocol::soe: return soe ? &soe->init_cmds : nullptr;
        case MailboxProtocol::foe:
        case MailboxProtocol::voe: return nullptr;
    }
    return nullptr;
}

const Object* Dictionary::find_object(std::uint32_t index) const {
    for (const auto& o : objects)
        if (o.index == index) return &o;
    return nullptr;
}

const DataType* Dictionary::find_data_type(std::string_view name) const {
    // Names of one length are told apart by their last letter first (DT1600, DT1601, ...): most
    // of those a lookup passes are then left without a call to compare the whole names.
    const std::size_t n = name.size();
    for (const auto& t : data_types)
        if (t.name.size() == n && (n == 0 || t.name[n - 1] == name[n - 1]) && std::string_view(t.name) == name) return &t;
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

const EtherCATInfo* EsiDocument::info_of(const Device& device) const {
    for (const auto& info : infos)
        for (const auto& candidate : info.devices)
            if (&candidate == &device) return &info;
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
