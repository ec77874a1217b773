// Entry reads and writes with the checks of a device's CoE server (sdo_access.hpp).

#include "sim/sdo_access.hpp"

#include <algorithm>

#include "esi/ethercat/mailbox.hpp"

namespace esi::sim {

bool is_rx_mapping(std::uint32_t index) { return index >= 0x1600 && index <= 0x17FF; }
bool is_tx_mapping(std::uint32_t index) { return index >= 0x1A00 && index <= 0x1BFF; }
bool is_assignment(std::uint32_t index) { return index >= 0x1C10 && index <= 0x1C2F; }

std::uint32_t mapped_bits(const CoeObject& mapping, std::uint8_t count) {
    std::uint32_t bits = 0;
    for (std::uint8_t i = 1; i <= count && i != 0; ++i) {
        const CoeEntry* e = mapping.entry(i);
        if (!e) return 0;
        bits += static_cast<std::uint32_t>(e->unsigned_value() & 0xFFu);
    }
    return bits;
}

namespace {

bool is_pdo_object(std::uint32_t index) { return is_rx_mapping(index) || is_tx_mapping(index) || is_assignment(index); }

// ETG.1000.6 5.6.7.4.7: data-type indices 0x0001–0x0007 map as gaps ("dummy entries").
bool is_gap(std::uint32_t index) { return index == 0 || (index >= 0x0001 && index <= 0x0007); }

std::uint32_t read_refusal(const CoeEntry& entry) {
    return entry.readable_somewhere() ? ethercat::sdo_abort::device_state : ethercat::sdo_abort::write_only;
}

std::uint32_t write_refusal(const CoeEntry& entry) {
    return entry.writable_somewhere() ? ethercat::sdo_abort::device_state : ethercat::sdo_abort::read_only;
}

}  // namespace

std::uint32_t ObjectAccess::read(std::uint16_t index, std::uint8_t subindex, bool complete, AlState state,
                                 std::vector<std::uint8_t>& out) const {
    const CoeObject* object = dictionary_.find(index);
    if (!object) return ethercat::sdo_abort::object_missing;
    if (!complete) {
        const CoeEntry* entry = object->entry(subindex);
        if (!entry) return ethercat::sdo_abort::subindex_missing;
        if (!entry->readable(state)) return read_refusal(*entry);
        out = entry->value;
        return ethercat::sdo_abort::none;
    }
    if (!rules_.complete_access) return ethercat::sdo_abort::no_complete_access;
    if (subindex > 1) return ethercat::sdo_abort::unsupported_access;
    const std::uint32_t bits = object->complete_bits(subindex);
    out.assign((bits + 7u) / 8u, 0);
    bool base_known = false;
    std::uint32_t base = 0;
    for (const CoeEntry& e : object->entries) {
        if (e.subindex < subindex) continue;
        if (!base_known) base = e.bit_offset;
        base_known = true;
        if (!e.readable(state)) return read_refusal(e);
        const std::uint32_t at = e.bit_offset - base;
        if (e.value.size() * 8u < e.bit_size || at + e.bit_size > out.size() * 8u) continue;
        copy_bits(e.value.data(), 0, out.data(), at, e.bit_size);
    }
    return ethercat::sdo_abort::none;
}

std::size_t ObjectAccess::write_limit(std::uint16_t index, std::uint8_t subindex, bool complete) const {
    const CoeObject* object = dictionary_.find(index);
    if (!object) return 0;
    if (complete) return (object->complete_bits(subindex) + 7u) / 8u;
    const CoeEntry* entry = object->entry(subindex);
    return entry ? entry->byte_size() : 0;
}

std::uint32_t ObjectAccess::write(std::uint16_t index, std::uint8_t subindex, bool complete, AlState state,
                                  std::span<const std::uint8_t> data) {
    CoeObject* object = dictionary_.find(index);
    if (!object) return ethercat::sdo_abort::object_missing;
    if (!complete) {
        CoeEntry* entry = object->entry(subindex);
        if (!entry) return ethercat::sdo_abort::subindex_missing;
        return write_entry(*object, *entry, state, data, true);
    }
    if (!rules_.complete_access) return ethercat::sdo_abort::no_complete_access;
    if (subindex > 1) return ethercat::sdo_abort::unsupported_access;
    const std::size_t limit = write_limit(index, subindex, true);
    if (data.size() > limit) return ethercat::sdo_abort::length_too_long;
    if (is_pdo_object(index) && state != AlState::preop) return ethercat::sdo_abort::device_state;

    // The whole object is written or nothing: keep the values to restore on a refusal.
    std::vector<std::vector<std::uint8_t>> saved;
    for (const CoeEntry& e : object->entries) saved.push_back(e.value);
    auto restore = [&](std::uint32_t code) {
        for (std::size_t i = 0; i < saved.size(); ++i) object->entries[i].value = saved[i];
        return code;
    };

    const bool pdo_object = is_pdo_object(index);
    CoeEntry* sub0 = object->entry(0);
    std::optional<std::uint8_t> new_count;
    // PDO objects: the entries are written with sub-index 0 at 0 and the count set last, as a
    // master does it entry by entry; so each step is checked the same way.
    if (pdo_object && sub0) sub0->set_unsigned(0);
    std::uint32_t base = 0;
    bool base_known = false;
    for (CoeEntry& e : object->entries) {
        if (e.subindex < subindex) continue;
        if (!base_known) base = e.bit_offset;
        base_known = true;
        const std::uint32_t at = e.bit_offset - base;
        if (at + e.bit_size > data.size() * 8u) break;  // a shorter stream ends the write
        std::vector<std::uint8_t> bytes(e.byte_size(), 0);
        copy_bits(data.data(), at, bytes.data(), 0, e.bit_size);
        if (e.subindex == 0 && object->code != object_code::var) {
            new_count = bytes.empty() ? 0 : bytes[0];
            if (!pdo_object && bytes != e.value && !e.writable(state)) return restore(write_refusal(e));
            continue;
        }
        if (!e.writable(state)) {
            if (bytes == saved[static_cast<std::size_t>(&e - object->entries.data())]) continue;
            return restore(write_refusal(e));
        }
        const std::uint32_t code = write_entry(*object, e, state, bytes, false);
        if (code != ethercat::sdo_abort::none) return restore(code);
    }
    if (sub0) {
        const std::uint8_t count = new_count ? *new_count : static_cast<std::uint8_t>(saved.front().empty() ? 0 : saved.front()[0]);
        if (pdo_object || new_count) {
            const std::vector<std::uint8_t> bytes(sub0->byte_size() ? sub0->byte_size() : 1, 0);
            std::vector<std::uint8_t> value = bytes;
            value[0] = count;
            const std::uint32_t code = write_entry(*object, *sub0, state, value, false);
            if (code != ethercat::sdo_abort::none) return restore(code);
        }
    }
    return ethercat::sdo_abort::none;
}

std::uint32_t ObjectAccess::write_entry(CoeObject& object, CoeEntry& entry, AlState state, std::span<const std::uint8_t> data,
                                        bool check_access) {
    const bool pdo_object = is_pdo_object(object.index);
    if (check_access && !entry.writable(state)) {
        // A PDO object's sub-index 0 is writable in PREOP only, whatever its flags say of other states.
        if (!(pdo_object && entry.writable(AlState::preop))) return write_refusal(entry);
    }
    if (pdo_object && state != AlState::preop) return ethercat::sdo_abort::device_state;
    const std::size_t size = entry.byte_size();
    if (data.size() > size) return ethercat::sdo_abort::length_too_long;
    if (data.size() < size && !entry.variable_length()) return ethercat::sdo_abort::length_too_short;
    std::vector<std::uint8_t> value(size, 0);
    std::copy(data.begin(), data.end(), value.begin());
    if (pdo_object) {
        CoeEntry probe = entry;
        probe.value = value;
        const std::uint32_t code = check_pdo_object_write(object, entry, probe.unsigned_value());
        if (code != ethercat::sdo_abort::none) return code;
    }
    entry.value = std::move(value);
    return ethercat::sdo_abort::none;
}

std::uint32_t ObjectAccess::check_pdo_object_write(const CoeObject& object, const CoeEntry& entry, std::uint64_t value) const {
    const CoeEntry* sub0 = object.entry(0);
    if (entry.subindex != 0) {
        if (sub0 && sub0->unsigned_value() != 0) return ethercat::sdo_abort::subindex_0_not_zero;
        if (is_assignment(object.index)) {
            const std::uint32_t sm = object.index - 0x1C10u;
            const SmRole role = sm < rules_.sm_roles.size() ? rules_.sm_roles[sm] : SmRole::unused;
            const bool ok = value == 0 || (role == SmRole::outputs && is_rx_mapping(static_cast<std::uint32_t>(value))) ||
                            (role == SmRole::inputs && is_tx_mapping(static_cast<std::uint32_t>(value)));
            if (!ok || (value != 0 && !dictionary_.find(static_cast<std::uint32_t>(value)))) return ethercat::sdo_abort::value_range;
            return ethercat::sdo_abort::none;
        }
        return check_mapping_entry(object.index, static_cast<std::uint32_t>(value));
    }
    if (value > object.max_subindex()) return ethercat::sdo_abort::value_too_high;
    const auto count = static_cast<std::uint8_t>(value);
    return is_assignment(object.index) ? check_assignment_complete(object, count) : check_mapping_complete(object, count);
}

std::uint32_t ObjectAccess::check_mapping_entry(std::uint16_t mapping_index, std::uint32_t mapped) const {
    const std::uint32_t index = mapped >> 16;
    const std::uint32_t subindex = (mapped >> 8) & 0xFFu;
    const std::uint32_t bits = mapped & 0xFFu;
    if (is_gap(index)) return ethercat::sdo_abort::none;
    const CoeObject* target = dictionary_.find(index);
    const CoeEntry* e = target ? target->entry(subindex) : nullptr;
    if (!e) return ethercat::sdo_abort::not_mappable;
    const std::uint16_t needed = is_rx_mapping(mapping_index) ? access_bit::rx_mappable : access_bit::tx_mappable;
    if (!(e->access & needed) || e->bit_size != bits) return ethercat::sdo_abort::not_mappable;
    return ethercat::sdo_abort::none;
}

std::uint32_t ObjectAccess::check_mapping_complete(const CoeObject& mapping, std::uint8_t count) const {
    std::uint64_t bits = 0;
    for (std::uint32_t i = 1; i <= count; ++i) {
        const CoeEntry* e = mapping.entry(i);
        if (!e) return ethercat::sdo_abort::value_too_high;
        const auto mapped = static_cast<std::uint32_t>(e->unsigned_value());
        if (const std::uint32_t code = check_mapping_entry(mapping.index, mapped); code != ethercat::sdo_abort::none) return code;
        bits += mapped & 0xFFu;
    }
    // The PDO must fit the SM it is assigned to (or could be: the first SM of its direction).
    const SmRole role = is_rx_mapping(mapping.index) ? SmRole::outputs : SmRole::inputs;
    std::uint32_t limit = 0;
    for (std::size_t sm = 0; sm < rules_.sm_roles.size(); ++sm)
        if (rules_.sm_roles[sm] == role && sm < rules_.sm_max_bits.size()) limit = std::max(limit, rules_.sm_max_bits[sm]);
    if (bits > limit) return ethercat::sdo_abort::pdo_length_exceeded;
    return ethercat::sdo_abort::none;
}

std::uint32_t ObjectAccess::check_assignment_complete(const CoeObject& assignment, std::uint8_t count) const {
    const std::uint32_t sm = assignment.index - 0x1C10u;
    std::uint64_t bits = 0;
    for (std::uint32_t i = 1; i <= count; ++i) {
        const CoeEntry* e = assignment.entry(i);
        if (!e) return ethercat::sdo_abort::value_too_high;
        const CoeObject* mapping = dictionary_.find(static_cast<std::uint32_t>(e->unsigned_value()));
        if (!mapping) return ethercat::sdo_abort::value_range;
        const CoeEntry* mapping_count = mapping->entry(0);
        bits += mapped_bits(*mapping, mapping_count ? static_cast<std::uint8_t>(mapping_count->unsigned_value()) : 0);
    }
    const std::uint32_t limit = sm < rules_.sm_max_bits.size() ? rules_.sm_max_bits[sm] : 0;
    if (bits > limit) return ethercat::sdo_abort::pdo_length_exceeded;
    return ethercat::sdo_abort::none;
}

}  // namespace esi::sim
