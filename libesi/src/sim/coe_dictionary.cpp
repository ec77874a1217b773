// The run-time object dictionary (coe_dictionary.hpp).

#include "sim/coe_dictionary.hpp"

#include <algorithm>

namespace esi::sim {

namespace {

std::uint16_t read_bit(AlState state) {
    switch (state) {
        case AlState::preop: return access_bit::read_preop;
        case AlState::safeop: return access_bit::read_safeop;
        case AlState::op: return access_bit::read_op;
        default: return 0;
    }
}

}  // namespace

bool CoeEntry::readable(AlState state) const { return (access & read_bit(state)) != 0; }

bool CoeEntry::writable(AlState state) const {
    // The write bits sit three places above the read bits of the same state.
    return (access & static_cast<std::uint16_t>(read_bit(state) << 3)) != 0;
}

bool CoeEntry::variable_length() const {
    if (!basic) return bit_size % 8 == 0 && bit_size > 0;
    return basic->type_class == TypeClass::visible_string || basic->type_class == TypeClass::octet_string ||
           basic->type_class == TypeClass::unicode_string || basic->type_class == TypeClass::domain;
}

std::uint64_t CoeEntry::unsigned_value() const {
    std::uint64_t out = 0;
    for (std::size_t i = 0; i < value.size() && i < 8; ++i) out |= std::uint64_t{value[i]} << (8 * i);
    if (bit_size < 64) out &= (std::uint64_t{1} << bit_size) - 1u;
    return out;
}

void CoeEntry::set_unsigned(std::uint64_t number) {
    for (std::size_t i = 0; i < value.size(); ++i) value[i] = i < 8 ? static_cast<std::uint8_t>(number >> (8 * i)) : 0;
}

CoeEntry* CoeObject::entry(std::uint32_t subindex) {
    return const_cast<CoeEntry*>(static_cast<const CoeObject*>(this)->entry(subindex));
}

const CoeEntry* CoeObject::entry(std::uint32_t subindex) const {
    for (const CoeEntry& e : entries)
        if (e.subindex == subindex) return &e;
    return nullptr;
}

std::uint8_t CoeObject::max_subindex() const { return entries.empty() ? 0 : entries.back().subindex; }

std::uint32_t CoeObject::complete_bits(std::uint8_t first) const {
    std::uint32_t start = 0;
    std::uint32_t end = 0;
    bool any = false;
    for (const CoeEntry& e : entries) {
        if (e.subindex < first) continue;
        if (!any) start = e.bit_offset;
        any = true;
        end = std::max(end, e.bit_offset + e.bit_size);
    }
    // Sub-index 0 travels as 8 bits padded to 16 (ETG.1000.6 5.6.2.1.2, complete access).
    if (first == 0 && code != object_code::var && end < 16) end = 16;
    return any ? end - start : 0;
}

CoeObject* CoeDictionary::find(std::uint32_t index) {
    return const_cast<CoeObject*>(static_cast<const CoeDictionary*>(this)->find(index));
}

const CoeObject* CoeDictionary::find(std::uint32_t index) const {
    auto it = std::lower_bound(objects_.begin(), objects_.end(), index,
                               [](const CoeObject& o, std::uint32_t i) { return o.index < i; });
    return it != objects_.end() && it->index == index ? &*it : nullptr;
}

CoeObject& CoeDictionary::add(CoeObject object) {
    auto it = std::lower_bound(objects_.begin(), objects_.end(), object.index,
                               [](const CoeObject& o, std::uint32_t i) { return o.index < i; });
    if (it != objects_.end() && it->index == object.index) return *it;
    return *objects_.insert(it, std::move(object));
}

void CoeDictionary::reset_values() {
    for (CoeObject& o : objects_)
        for (CoeEntry& e : o.entries) e.value = e.default_value;
}

void copy_bits(const std::uint8_t* source, std::size_t from, std::uint8_t* target, std::size_t to, std::size_t bits) {
    if (from % 8 == 0 && to % 8 == 0) {
        const std::size_t whole = bits / 8;
        std::copy(source + from / 8, source + from / 8 + whole, target + to / 8);
        from += whole * 8;
        to += whole * 8;
        bits -= whole * 8;
    }
    for (std::size_t i = 0; i < bits; ++i) {
        const bool bit = (source[(from + i) / 8] >> ((from + i) % 8)) & 1u;
        std::uint8_t& t = target[(to + i) / 8];
        const auto mask = static_cast<std::uint8_t>(1u << ((to + i) % 8));
        t = bit ? static_cast<std::uint8_t>(t | mask) : static_cast<std::uint8_t>(t & ~mask);
    }
}

}  // namespace esi::sim
