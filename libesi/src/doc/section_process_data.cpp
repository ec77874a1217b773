// The process-data sections of a page: each SyncManager's default image as one picture, and every
// PDO as a table and a picture.

#include <string>

#include "doc/markup.hpp"
#include "doc/process_data.hpp"
#include "doc/sections.hpp"
#include "esi/plural.hpp"

namespace esi::doc {

namespace {

std::string size_text(std::uint64_t bits) {
    if (bits % 8 == 0) return std::to_string(bits / 8) + (bits == 8 ? " byte" : " bytes");
    return std::to_string(bits) + " bits";
}

std::string offset_text(std::uint64_t bit_offset) { return std::to_string(bit_offset / 8) + "." + std::to_string(bit_offset % 8); }

std::string pdo_list_text(const std::vector<const Pdo*>& pdos) {
    std::string out;
    for (const Pdo* p : pdos) out += (out.empty() ? "" : ", ") + hex(p->index, 4);
    return out;
}

std::string flags_text(const Pdo& pdo) {
    std::string out;
    const auto add = [&](bool on, const char* word) {
        if (on) out += (out.empty() ? "" : ", ") + std::string(word);
    };
    add(pdo.fixed.value_or(false), "fixed");
    add(pdo.mandatory.value_or(false), "mandatory");
    add(pdo.is_virtual.value_or(false), "virtual");
    add(pdo.index_depend_on_slot.value_or(false), "index depends on slot");
    add(pdo.overwritten_by_module.value_or(false), "overwritten by module");
    return out;
}

ViewValue pdo_view(const Pdo& pdo, std::size_t position, std::string_view owner, const PageContext& context) {
    ViewArena& arena = *context.arena;
    const bool rx = pdo.direction == PdoDirection::rx;
    const std::string id = std::string(owner) + (rx ? "-rx" : "-tx") + std::to_string(position);
    const std::string key_prefix = std::string(owner) + (rx ? ":R" : ":T") + std::to_string(position) + ":";
    const std::string name = context.text(pdo.names);

    PageObject o(arena);
    o.add("id", id);
    o.add("kind", ViewValue::of_static(pdo.element_name()));
    o.add("direction", ViewValue::of_static(rx ? "outputs" : "inputs"));
    o.add("index_hex", hex(pdo.index, 4));
    o.add("name", name);
    o.add("assigned", pdo.sm.has_value());
    o.add("sm", pdo.sm);
    std::string excludes;
    for (const auto& x : pdo.excludes) excludes += (excludes.empty() ? "" : ", ") + hex(x.index, 4);
    o.add("excludes", excludes);
    o.add("flags", flags_text(pdo));
    o.add("bit_size", pdo.bit_size());
    o.add("size", size_text(pdo.bit_size()));
    o.add("entry_count", pdo.entries.size());

    const std::vector<LayoutField> fields = pdo_fields(pdo, context.lcid);
    BitLayoutOptions picture;
    picture.id = "pic-" + id;
    picture.title = std::string(pdo.element_name()) + " " + hex(pdo.index, 4) + (name.empty() ? "" : " " + name) + ": " +
                    std::to_string(pdo.entries.size()) + (pdo.entries.size() == 1 ? " entry, " : " entries, ") + size_text(pdo.bit_size());
    o.add("svg", render_bit_layout_svg(fields, picture));

    ListBuilder entries(arena);
    for (std::size_t i = 0; i < pdo.entries.size(); ++i) {
        const PdoEntry& e = pdo.entries[i];
        const LayoutField& f = fields[i];
        PageObject entry(arena);
        entry.add("key", key_prefix + std::to_string(i));
        entry.add("address", f.address);
        entry.add("name", f.name);
        entry.add("type", f.type);
        entry.add("bit_len", e.bit_len);
        entry.add("offset", offset_text(f.bit_offset));
        entry.add("padding", f.padding);
        entries.add(entry.finish());
    }
    o.add("entries", entries.finish());
    return o.finish();
}

}  // namespace

ViewValue pdos_list(const std::vector<Pdo>& rx, const std::vector<Pdo>& tx, std::string_view owner, const PageContext& context) {
    ListBuilder list(*context.arena);
    for (std::size_t i = 0; i < rx.size(); ++i) list.add(pdo_view(rx[i], i, owner, context));
    for (std::size_t i = 0; i < tx.size(); ++i) list.add(pdo_view(tx[i], i, owner, context));
    return list.finish();
}

ViewValue process_images_list(const Device& device, const PageContext& context) {
    ViewArena& arena = *context.arena;
    ListBuilder list(arena);
    for (const SmImage& image : sm_images(device, context.lcid)) {
        const SyncManager* sm = image.sm < device.sms.size() ? &device.sms[image.sm] : nullptr;
        PageObject o(arena);
        const std::string id = "sm" + std::to_string(image.sm);
        o.add("id", id);
        o.add("sm", image.sm);
        o.add("sm_type", sm ? sm->type : std::string("(no such SyncManager)"));
        o.add("start_hex", sm && sm->start_address ? hex(*sm->start_address, 4) : std::string());
        o.add("default_size", sm ? sm->default_size : std::nullopt);
        o.add("default_size_text", sm && sm->default_size ? counted(*sm->default_size, "byte") : std::string());
        o.add("bit_size", image.bit_size);
        o.add("size", size_text(image.bit_size));
        o.add("pdos", pdo_list_text(image.pdos));
        BitLayoutOptions picture;
        picture.id = "pic-" + id;
        picture.title = "Process image of SM" + std::to_string(image.sm) + (sm ? " (" + sm->type + ")" : std::string()) + ": " +
                        size_text(image.bit_size) + " from " + (image.pdos.size() == 1 ? "PDO " : "PDOs ") + pdo_list_text(image.pdos);
        o.add("svg", render_bit_layout_svg(image.fields, picture));
        list.add(o.finish());
    }
    return list.finish();
}

}  // namespace esi::doc
