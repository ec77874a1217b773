#include "esi/derive/object_builder.hpp"

#include <algorithm>
#include <cstdio>

#include "esi/data_types.hpp"
#include "esi/model/object_layout.hpp"

namespace esi {

std::string subindex_name(std::uint32_t subindex) {
    char buffer[24];
    std::snprintf(buffer, sizeof buffer, "SubIndex %03u", subindex);
    return buffer;
}

std::string unique_type_name(const Dictionary& dictionary, const std::string& base) {
    if (!dictionary.find_data_type(base)) return base;
    for (int i = 2;; ++i) {
        std::string candidate = base + "_" + std::to_string(i);
        if (!dictionary.find_data_type(candidate)) return candidate;
    }
}

std::uint64_t type_bit_size(const Dictionary& dictionary, const std::string& type_name) {
    // Basic types, STRING(n) and arrays of basic types have their size in the name: no need to
    // search the dictionary's DataTypes (a linear list) for the common case.
    if (const auto implied = implied_bit_size(type_name)) return *implied;
    const ResolvedType resolved = resolve_type(&dictionary, type_name);
    if (resolved.cycle) return 0;
    return resolved.bit_size;
}

namespace {

ObjectInfo count_info(std::uint64_t count) {
    ObjectInfo info;
    info.default_value = Number::from_unsigned(count);
    return info;
}

// ETG.1000.6: sub-index 0 of an ARRAY/RECORD is the UNSIGNED8 number of entries. A record that
// writes a sub-index 0 of another type keeps data there (STÖBER A261.0 is a UDINT error code, and
// 2 in it means "cycle time < 1 ms"), so only an UNSIGNED8 one is given the count as default.
bool is_entry_count(const DataTypeSubItem& item) {
    const BasicType* basic = find_basic_type(item.type);
    if (!basic) {
        const std::string_view standard = standard_type_name_for(item.type);
        basic = standard.empty() ? nullptr : find_basic_type(standard);
    }
    return basic && basic->coe_code == 0x0005;
}

DataTypeSubItem sub0_item(const std::optional<ObjectFlags>& flags) {
    DataTypeSubItem s;
    s.subindex = 0;
    s.name = subindex_name(0);
    s.type = "USINT";
    s.bit_size = 8;
    s.bit_offset = 0;
    s.flags = flags;
    return s;
}

}  // namespace

std::string build_record(Dictionary& dictionary, Object& object, const std::string& type_name, std::vector<RecordEntry> entries,
                         const std::optional<ObjectFlags>& sub0_flags) {
    std::stable_sort(entries.begin(), entries.end(),
                     [](const RecordEntry& a, const RecordEntry& b) { return a.item.subindex.value_or(0) < b.item.subindex.value_or(0); });
    std::uint32_t highest = 0;
    for (const auto& e : entries) highest = std::max(highest, e.item.subindex.value_or(0));
    if (entries.empty() || entries.front().item.subindex.value_or(0) != 0) {
        RecordEntry sub0;
        sub0.item = sub0_item(sub0_flags);
        sub0.item.pos = object.pos;
        sub0.info = count_info(highest);
        entries.insert(entries.begin(), std::move(sub0));
    } else if (is_entry_count(entries.front().item) &&
               (!entries.front().info || (!entries.front().info->default_value && !entries.front().info->default_data))) {
        if (!entries.front().info) entries.front().info = count_info(highest);
        else entries.front().info->default_value = Number::from_unsigned(highest);
    }

    DataType type;
    type.name = type_name;
    type.name_pos = object.pos;
    type.pos = object.pos;
    std::uint64_t offset = 0;
    for (auto& e : entries) {
        if (e.item.bit_size == 0) e.item.bit_size = type_bit_size(dictionary, e.item.type);
        if (e.item.bit_size == 0)
            return "the type '" + e.item.type + "' of sub-index " + std::to_string(e.item.subindex.value_or(0)) +
                   " has no known size; give bit_size";
        if (!e.explicit_offset) {
            // Sub-index 0 is followed by 8 bits of padding; values of a byte or more are byte-aligned.
            if (e.item.subindex.value_or(0) != 0 && offset < 16) offset = 16;
            if (e.item.bit_size >= 8 && offset % 8 != 0) offset += 8 - offset % 8;
            e.item.bit_offset = offset;
        }
        offset = std::max(offset, e.item.bit_offset + e.item.bit_size);
    }
    type.bit_size = (offset + 7) / 8 * 8;

    ObjectInfo info = object.info.value_or(ObjectInfo{});
    info.sub_items.clear();
    for (auto& e : entries) {
        if (e.info) {
            ObjectSubItemInfo sub;
            sub.name = e.item.name;
            sub.info = std::move(*e.info);
            sub.pos = e.item.pos;
            info.sub_items.push_back(std::move(sub));
        }
        type.sub_items.push_back(std::move(e.item));
    }
    object.type = type.name;
    object.type_pos = object.pos;
    object.bit_size = type.bit_size;
    if (!info.sub_items.empty() || object.info) object.info = std::move(info);
    dictionary.data_types.push_back(std::move(type));
    return {};
}

std::string build_array(Dictionary& dictionary, Object& object, const std::string& type_name, const std::string& element_type,
                        std::uint32_t count, std::vector<std::optional<ObjectInfo>> infos,
                        const std::optional<ObjectFlags>& sub0_flags, const std::optional<ObjectFlags>& element_flags,
                        std::vector<std::string> names) {
    const std::uint64_t element_bits = type_bit_size(dictionary, element_type);
    if (element_bits == 0) return "the element type '" + element_type + "' has no known size";
    if (count == 0 || count > 255) return "an array holds 1 to 255 elements (sub-indices 1..255), not " + std::to_string(count);

    DataType elements;
    elements.name = unique_type_name(dictionary, type_name + "ARR");
    elements.base_type = element_type;
    elements.bit_size = element_bits * count;
    elements.array_info.push_back(ArrayInfo{1, count, object.pos});
    elements.name_pos = elements.pos = object.pos;

    DataType type;
    type.name = type_name;
    type.name_pos = type.pos = object.pos;
    type.sub_items.push_back(sub0_item(sub0_flags));
    type.sub_items.back().pos = object.pos;
    DataTypeSubItem items;
    items.name = "Elements";
    items.type = elements.name;
    items.bit_size = elements.bit_size;
    items.bit_offset = 16;
    items.flags = element_flags;
    items.pos = object.pos;
    type.sub_items.push_back(std::move(items));
    type.bit_size = 16 + elements.bit_size;

    infos.resize(count + 1u);
    if (!infos[0]) infos[0] = count_info(count);
    ObjectInfo info = object.info.value_or(ObjectInfo{});
    info.sub_items.clear();
    for (std::uint32_t sub = 0; sub <= count; ++sub) {
        ObjectSubItemInfo item;
        item.name = sub < names.size() && !names[sub].empty() ? names[sub] : subindex_name(sub);
        if (infos[sub]) item.info = std::move(*infos[sub]);
        item.pos = object.pos;
        info.sub_items.push_back(std::move(item));
    }
    object.type = type.name;
    object.type_pos = object.pos;
    object.bit_size = type.bit_size;
    object.info = std::move(info);
    dictionary.data_types.push_back(std::move(elements));
    dictionary.data_types.push_back(std::move(type));
    return {};
}

}  // namespace esi
