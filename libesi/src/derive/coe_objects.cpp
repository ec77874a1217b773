// The communication objects that follow from the rest of a device description:
//   0x1000 Device type      CiA 301 7.5.2.1: profile number (low word), additional info (high word)
//   0x1018 Identity         CiA 301 7.5.2.20: vendor id, product code, revision, serial number
//   0x16xx/0x1Axx mapping   ETG.1000.6 5.6.7.4.7: one UDINT per entry, index<<16 | sub<<8 | bits
//   0x1C10+n assignment     ETG.1000.6 5.6.7.4.9: UINT PDO indices assigned to SM n (the servo
//                           manuals' UINT8 for these entries is wrong: 0x1600 needs 16 bits)
//   0x1C00 SM types         ETG.1000.6 5.6.7.4.8: 1 MBoxOut, 2 MBoxIn, 3 Outputs, 4 Inputs, 0 unused
// An object the source declares itself is never replaced.

#include "derive/steps.hpp"
#include "esi/derive/object_builder.hpp"

namespace esi::derive {

namespace {

ObjectFlags access_flags(std::string access, std::optional<std::string> category = std::nullopt) {
    ObjectFlags f;
    f.access = std::move(access);
    f.category = std::move(category);
    return f;
}

Object named_object(std::uint32_t index, std::string name, SourcePos pos) {
    Object o;
    o.index = index;
    o.index_pos = pos;
    o.pos = pos;
    o.names.push_back(LocalizedText{std::move(name), std::nullopt, pos});
    return o;
}

bool has_object(const Dictionary& d, std::uint32_t index) { return d.find_object(index) != nullptr; }

void add(Dictionary& d, Object o, const std::string& error, Context& context) {
    if (!error.empty()) {
        context.error(o.pos, "derive-object", "cannot derive object " + hex4(o.index) + ": " + error);
        return;
    }
    d.objects.push_back(std::move(o));
}

RecordEntry udint_entry(std::uint32_t subindex, std::string name, std::uint64_t value, const ObjectFlags& flags, SourcePos pos) {
    RecordEntry e;
    e.item.subindex = subindex;
    e.item.name = std::move(name);
    e.item.type = "UDINT";
    e.item.bit_size = 32;
    e.item.flags = flags;
    e.item.pos = pos;
    ObjectInfo info;
    info.default_value = Number::from_unsigned(value);
    e.info = std::move(info);
    return e;
}

std::uint32_t sm_type_code(const std::string& type) {
    if (type == "MBoxOut") return 1;
    if (type == "MBoxIn") return 2;
    if (type == "Outputs") return 3;
    if (type == "Inputs") return 4;
    return 0;
}

}  // namespace

void derive_standard_objects(Device& device, const DeviceIntent& intent, Context& context) {
    Dictionary* d = dictionary_of(device, false);
    if (!d) return;
    if (intent.options.device_type_object && !has_object(*d, 0x1000)) {
        std::uint32_t value = 0;
        for (const auto& p : device.profiles) {
            if (!p.profile_no) continue;
            value = (static_cast<std::uint32_t>(*p.profile_no) & 0xFFFFu) |
                    ((static_cast<std::uint32_t>(p.add_info.value_or(0)) & 0xFFFFu) << 16);
            break;
        }
        Object o = named_object(0x1000, "Device type", device.pos);
        o.type = "UDINT";
        o.type_pos = device.pos;
        o.bit_size = 32;
        ObjectInfo info;
        info.default_value = Number::from_unsigned(value);
        o.info = std::move(info);
        o.flags = access_flags("ro", "m");
        d->objects.push_back(std::move(o));
    }
    if (intent.options.identity_object && !has_object(*d, 0x1018)) {
        if (!intent.vendor_id || !device.type.product_code || !device.type.revision_no) {
            context.error(device.pos, "derive-object",
                          "cannot derive the identity object 0x1018 without vendor id, product code and revision");
            return;
        }
        const ObjectFlags ro = access_flags("ro");
        std::vector<RecordEntry> entries;
        entries.push_back(udint_entry(1, "Vendor ID", *intent.vendor_id, ro, device.pos));
        entries.push_back(udint_entry(2, "Product code", *device.type.product_code, ro, device.pos));
        entries.push_back(udint_entry(3, "Revision", *device.type.revision_no, ro, device.pos));
        entries.push_back(udint_entry(4, "Serial number", device.type.serial_no.value_or(0), ro, device.pos));
        Object o = named_object(0x1018, "Identity", device.pos);
        o.flags = access_flags("ro", "m");
        const std::string error = build_record(*d, o, unique_type_name(*d, "DT1018"), std::move(entries), ro);
        add(*d, std::move(o), error, context);
    }
}

void derive_mapping_objects(Device& device, const DeviceIntent& intent, Context& context) {
    Dictionary* d = dictionary_of(device, false);
    if (!d) return;
    for (const auto* list : {&device.rx_pdos, &device.tx_pdos}) {
        for (const Pdo& pdo : *list) {
            if (has_object(*d, pdo.index)) continue;
            const bool fixed = pdo.fixed.value_or(false);
            std::size_t capacity = pdo.entries.size();
            // A flexible PDO offers as many mapping entries as the device allows (STÖBER §7.1.1:
            // "ein Parameter mit sechs Subelementen" per PDO channel), so a master can remap it.
            if (!fixed && intent.limits.max_entries_per_pdo && *intent.limits.max_entries_per_pdo > capacity)
                capacity = *intent.limits.max_entries_per_pdo;
            if (capacity > 254) {
                context.error(pdo.pos, "derive-object",
                              "PDO " + hex4(pdo.index) + " has " + std::to_string(capacity) +
                                  " entries; a mapping object holds at most 254 (sub-indices 1..254)");
                continue;
            }
            const ObjectFlags flags = access_flags(fixed ? "ro" : "rw");
            std::vector<RecordEntry> entries;
            for (std::size_t k = 0; k < capacity; ++k) {
                std::uint64_t value = 0;
                if (k < pdo.entries.size()) {
                    const PdoEntry& e = pdo.entries[k];
                    value = (std::uint64_t{e.index} << 16) | (std::uint64_t{e.effective_subindex() & 0xFFu} << 8) | (e.bit_len & 0xFFu);
                }
                const auto sub = static_cast<std::uint32_t>(k + 1);
                entries.push_back(udint_entry(sub, subindex_name(sub), value, flags, pdo.pos));
            }
            const std::string prefix = pdo.direction == PdoDirection::rx ? "RxPDO-Map " : "TxPDO-Map ";
            const std::string pdo_name = primary_text(pdo.names);
            Object o = named_object(pdo.index, prefix + (pdo_name.empty() ? hex4(pdo.index) : pdo_name), pdo.pos);
            o.flags = flags;
            RecordEntry sub0;
            sub0.item.subindex = 0;
            sub0.item.name = subindex_name(0);
            sub0.item.type = "USINT";
            sub0.item.bit_size = 8;
            sub0.item.flags = flags;
            sub0.item.pos = pdo.pos;
            ObjectInfo count;
            count.default_value = Number::from_unsigned(pdo.entries.size());
            sub0.info = std::move(count);
            entries.insert(entries.begin(), std::move(sub0));
            const std::string error = build_record(*d, o, unique_type_name(*d, "DT" + hex4(pdo.index).substr(2)), std::move(entries), flags);
            add(*d, std::move(o), error, context);
        }
    }
}

void derive_assignment_objects(Device& device, Context& context) {
    Dictionary* d = dictionary_of(device, false);
    if (!d) return;
    const bool pdo_assign = device.mailbox && device.mailbox->coe && device.mailbox->coe->pdo_assign.value_or(false);
    for (std::size_t n = 0; n < device.sms.size() && n < 16; ++n) {
        const SyncManager& sm = device.sms[n];
        const bool outputs = sm.type == "Outputs";
        if (!outputs && sm.type != "Inputs") continue;
        const auto index = static_cast<std::uint32_t>(0x1C10 + n);
        if (has_object(*d, index)) continue;
        const std::vector<Pdo>& pdos = outputs ? device.rx_pdos : device.tx_pdos;
        std::vector<const Pdo*> candidates;
        std::vector<std::uint32_t> assigned;
        for (const Pdo& p : pdos) {
            bool excluded = false;
            for (auto x : p.excluded_sms) excluded = excluded || x == n;
            if (excluded || (p.sm && *p.sm != n)) continue;
            candidates.push_back(&p);
            if (p.sm) assigned.push_back(p.index);
        }
        if (candidates.empty()) continue;
        const bool changeable = pdo_assign || assigned.size() < candidates.size();
        const ObjectFlags flags = access_flags(changeable ? "rw" : "ro");
        const auto count = static_cast<std::uint32_t>(candidates.size());
        std::vector<std::optional<ObjectInfo>> infos(count + 1u);
        ObjectInfo sub0;
        sub0.default_value = Number::from_unsigned(assigned.size());
        infos[0] = std::move(sub0);
        for (std::uint32_t k = 0; k < count; ++k) {
            ObjectInfo info;
            info.default_value = Number::from_unsigned(k < assigned.size() ? assigned[k] : 0);
            infos[k + 1] = std::move(info);
        }
        Object o = named_object(index, outputs ? "RxPDO assign" : "TxPDO assign", sm.pos);
        o.flags = flags;
        const std::string error =
            build_array(*d, o, unique_type_name(*d, "DT" + hex4(index).substr(2)), "UINT", count, std::move(infos), flags, flags);
        add(*d, std::move(o), error, context);
    }
}

void derive_sm_types_object(Device& device, Context& context) {
    Dictionary* d = dictionary_of(device, false);
    if (!d || device.sms.empty() || has_object(*d, 0x1C00)) return;
    const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(device.sms.size(), 32));
    std::vector<std::optional<ObjectInfo>> infos(count + 1u);
    for (std::uint32_t k = 0; k < count; ++k) {
        ObjectInfo info;
        info.default_value = Number::from_unsigned(sm_type_code(device.sms[k].type));
        infos[k + 1] = std::move(info);
    }
    const ObjectFlags ro = access_flags("ro", "m");
    Object o = named_object(0x1C00, "Sync manager type", device.sms.front().pos);
    o.flags = ro;
    const std::string error = build_array(*d, o, unique_type_name(*d, "DT1C00"), "USINT", count, std::move(infos), ro, ro);
    add(*d, std::move(o), error, context);
}

}  // namespace esi::derive
