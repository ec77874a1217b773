// SDO Information responses (sdo_info.hpp). Header of every frame: opcode (bit 7: more
// fragments follow), a reserved byte, the number of fragments still to come (2 bytes).

#include "sim/sdo_info.hpp"

#include <algorithm>

#include "esi/ethercat/mailbox.hpp"

namespace esi::sim {

namespace {

namespace op = ethercat::sdo_info_opcode;

constexpr std::size_t header_bytes = 4;
// Value info bits a request may set for optional data (ETG.1000.6 Table 47); only the default
// value is sent, the others are left out and cleared in the response.
constexpr std::uint8_t value_info_default = 0x10;

void put_u16(std::vector<std::uint8_t>& out, std::uint32_t v) {
    out.push_back(static_cast<std::uint8_t>(v));
    out.push_back(static_cast<std::uint8_t>(v >> 8));
}

// The payload cut into fragments of the room left after the header; `unit` keeps fragments a
// multiple of it (the object list travels as 16-bit words).
std::vector<std::vector<std::uint8_t>> fragments(std::uint8_t opcode, const std::vector<std::uint8_t>& payload,
                                                 std::size_t room, std::size_t unit) {
    std::vector<std::vector<std::uint8_t>> out;
    std::size_t per = room > header_bytes ? room - header_bytes : 0;
    per -= per % unit;
    if (per == 0) return out;
    const std::size_t count = std::max<std::size_t>(1, (payload.size() + per - 1) / per);
    if (count > 0xFFFF) return out;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t left = count - 1 - i;
        std::vector<std::uint8_t> f{static_cast<std::uint8_t>(opcode | (left ? 0x80 : 0)), 0};
        put_u16(f, static_cast<std::uint32_t>(left));
        const std::size_t from = i * per;
        const std::size_t to = std::min(payload.size(), from + per);
        f.insert(f.end(), payload.begin() + static_cast<std::ptrdiff_t>(from), payload.begin() + static_cast<std::ptrdiff_t>(to));
        out.push_back(std::move(f));
    }
    return out;
}

std::vector<std::vector<std::uint8_t>> error(std::uint32_t code) {
    std::vector<std::uint8_t> f{op::error, 0, 0, 0};
    for (int i = 0; i < 4; ++i) f.push_back(static_cast<std::uint8_t>(code >> (8 * i)));
    return {std::move(f)};
}

// List types (ETG.1000.6 Table 44): 1 all, 2 RxPDO-mappable, 3 TxPDO-mappable, 4 backup,
// 5 settings. An object is in a list when one of its entries has the property.
bool in_list(const CoeObject& object, std::uint16_t list) {
    if (list == 1) return true;
    const std::uint16_t bit = list == 2   ? access_bit::rx_mappable
                              : list == 3 ? access_bit::tx_mappable
                              : list == 4 ? access_bit::backup
                                          : access_bit::setting;
    return std::any_of(object.entries.begin(), object.entries.end(), [&](const CoeEntry& e) { return (e.access & bit) != 0; });
}

}  // namespace

std::vector<std::vector<std::uint8_t>> sdo_info_response(const CoeDictionary& dictionary, std::span<const std::uint8_t> request,
                                                         std::size_t room) {
    if (request.size() < header_bytes) return error(0x05040001);
    const std::uint8_t opcode = request[0] & 0x7F;
    const std::span<const std::uint8_t> data = request.subspan(header_bytes);
    if (opcode == op::get_od_list) {
        if (data.size() < 2) return error(ethercat::sdo_abort::command_specifier);
        const auto list = static_cast<std::uint16_t>(data[0] | (data[1] << 8));
        if (list > 5) return error(ethercat::sdo_abort::value_range);
        std::vector<std::uint8_t> payload;
        put_u16(payload, list);
        if (list == 0) {  // the length of every list
            for (std::uint16_t l = 1; l <= 5; ++l)
                put_u16(payload, static_cast<std::uint32_t>(std::count_if(dictionary.objects().begin(), dictionary.objects().end(),
                                                                          [&](const CoeObject& o) { return in_list(o, l); })));
        } else {
            for (const CoeObject& o : dictionary.objects())
                if (in_list(o, list)) put_u16(payload, o.index);
        }
        return fragments(op::od_list_response, payload, room, 2);
    }
    if (opcode == op::get_object_description) {
        if (data.size() < 2) return error(ethercat::sdo_abort::command_specifier);
        const CoeObject* object = dictionary.find(static_cast<std::uint32_t>(data[0] | (data[1] << 8)));
        if (!object) return error(ethercat::sdo_abort::object_missing);
        std::vector<std::uint8_t> payload;
        put_u16(payload, object->index);
        put_u16(payload, object->data_type);
        payload.push_back(object->max_subindex());
        payload.push_back(object->code);
        payload.insert(payload.end(), object->name.begin(), object->name.end());
        return fragments(op::object_description_response, payload, room, 1);
    }
    if (opcode == op::get_entry_description) {
        if (data.size() < 4) return error(ethercat::sdo_abort::command_specifier);
        const CoeObject* object = dictionary.find(static_cast<std::uint32_t>(data[0] | (data[1] << 8)));
        if (!object) return error(ethercat::sdo_abort::object_missing);
        const CoeEntry* entry = object->entry(data[2]);
        if (!entry) return error(ethercat::sdo_abort::subindex_missing);
        const auto value_info = static_cast<std::uint8_t>(data[3] & (0x07 | value_info_default));
        std::vector<std::uint8_t> payload;
        put_u16(payload, object->index);
        payload.push_back(entry->subindex);
        payload.push_back(value_info);
        put_u16(payload, entry->data_type);
        put_u16(payload, entry->bit_size);
        put_u16(payload, entry->access);
        if (value_info & value_info_default) payload.insert(payload.end(), entry->default_value.begin(), entry->default_value.end());
        payload.insert(payload.end(), entry->name.begin(), entry->name.end());
        return fragments(op::entry_description_response, payload, room, 1);
    }
    return error(ethercat::sdo_abort::command_specifier);
}

}  // namespace esi::sim
