// Process data layout and copying (process_image.hpp).

#include "sim/process_image.hpp"

namespace esi::sim {

std::vector<SmProcessData> lay_out_process_data(const CoeDictionary& dictionary, const std::vector<SmRole>& roles) {
    std::vector<SmProcessData> out;
    for (std::size_t sm = 0; sm < roles.size() && sm < 32; ++sm) {
        if (roles[sm] != SmRole::outputs && roles[sm] != SmRole::inputs) continue;
        SmProcessData data;
        data.sm = static_cast<std::uint8_t>(sm);
        data.role = roles[sm];
        const CoeObject* assignment = dictionary.find(static_cast<std::uint32_t>(0x1C10 + sm));
        const CoeEntry* assigned = assignment ? assignment->entry(0) : nullptr;
        const std::uint64_t pdo_count = assigned ? assigned->unsigned_value() : 0;
        for (std::uint32_t i = 1; i <= pdo_count && i <= 255; ++i) {
            const CoeEntry* pdo = assignment->entry(i);
            const CoeObject* mapping = pdo ? dictionary.find(static_cast<std::uint32_t>(pdo->unsigned_value())) : nullptr;
            const CoeEntry* mapped = mapping ? mapping->entry(0) : nullptr;
            const std::uint64_t entry_count = mapped ? mapped->unsigned_value() : 0;
            for (std::uint32_t k = 1; k <= entry_count && k <= 255; ++k) {
                const CoeEntry* e = mapping->entry(k);
                if (!e) continue;
                const auto value = static_cast<std::uint32_t>(e->unsigned_value());
                MappedEntry m;
                m.index = static_cast<std::uint16_t>(value >> 16);
                m.subindex = static_cast<std::uint8_t>(value >> 8);
                m.bit_len = value & 0xFFu;
                m.bit_offset = data.bits;
                data.bits += m.bit_len;
                data.entries.push_back(m);
            }
        }
        out.push_back(std::move(data));
    }
    return out;
}

namespace {

// The entry a mapped item names, when it exists with the mapped size.
template <class Dictionary>
auto* target(Dictionary& dictionary, const MappedEntry& m) {
    auto* o = dictionary.find(m.index);
    auto* e = o ? o->entry(m.subindex) : nullptr;
    return e && e->bit_size == m.bit_len && e->value.size() * 8u >= m.bit_len ? e : decltype(e){};
}

}  // namespace

void objects_to_buffer(const SmProcessData& layout, const CoeDictionary& dictionary, std::span<std::uint8_t> buffer) {
    for (const MappedEntry& m : layout.entries) {
        const CoeEntry* e = target(dictionary, m);
        if (!e || m.bit_offset + m.bit_len > buffer.size() * 8u) continue;
        copy_bits(e->value.data(), 0, buffer.data(), m.bit_offset, m.bit_len);
    }
}

void buffer_to_objects(const SmProcessData& layout, std::span<const std::uint8_t> buffer, CoeDictionary& dictionary) {
    for (const MappedEntry& m : layout.entries) {
        CoeEntry* e = target(dictionary, m);
        if (!e || m.bit_offset + m.bit_len > buffer.size() * 8u) continue;
        copy_bits(buffer.data(), m.bit_offset, e->value.data(), 0, m.bit_len);
    }
}

}  // namespace esi::sim
