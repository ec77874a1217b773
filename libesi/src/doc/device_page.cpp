#include "doc/device_page.hpp"

#include <array>

#include "doc/markup.hpp"
#include "doc/sections.hpp"

namespace esi::doc {

namespace {

// Physics letters (ETG.2000 DeviceType@Physics, one per port): Y and H MII, K E-Bus, space none.
std::string_view port_kind(char letter) {
    switch (letter) {
        case 'Y': return "MII (100BASE-TX)";
        case 'H': return "MII (100BASE-FX)";
        case 'K': return "E-Bus (LVDS)";
        case ' ': return "not used";
        default: return "unknown";
    }
}

ViewValue ports_list(const Device& device, ViewArena& arena) {
    ListBuilder list(arena);
    for (std::size_t i = 0; i < device.physics.size() && i < 4; ++i) {
        PageObject o(arena);
        o.add("port", std::string(1, static_cast<char>('A' + i)));
        o.add("letter", std::string(1, device.physics[i]));
        o.add("kind", ViewValue::of_static(port_kind(device.physics[i])));
        list.add(o.finish());
    }
    return list.finish();
}

std::string profiles_text(const Device& device) {
    std::string out;
    for (const Profile& p : device.profiles)
        if (p.profile_no) out += (out.empty() ? "" : ", ") + std::to_string(*p.profile_no);
    return out;
}

bool is_present(const ViewValue& v) { return v.kind == ViewValue::Kind::list ? v.size > 0 : v.kind != ViewValue::Kind::null; }

class Toc {
public:
    explicit Toc(ViewArena& arena) : list_(arena) {}
    void add(bool present, std::string_view id, std::string_view title) {
        if (!present) return;
        PageObject o(list_.arena());
        o.add("id", ViewValue::of_static(id));
        o.add("title", ViewValue::of_static(title));
        list_.add(o.finish());
    }
    ViewValue finish() { return list_.finish(); }

private:
    ListBuilder list_;
};

}  // namespace

std::string device_title(const Device& device, const PageContext& context) {
    const std::string& name = context.text(device.names);
    if (name.empty()) return device.type.text;
    if (device.type.text.empty() || name == device.type.text) return name;
    return name + " (" + device.type.text + ")";
}

ViewValue device_view(const Device& device, const PageContext& context) {
    ViewArena& arena = *context.arena;
    const ViewValue mailbox = mailbox_section(device, context);
    const ViewValue sms = sync_managers_list(device, context);
    const ViewValue fmmus = fmmus_list(device, context);
    const ViewValue images = process_images_list(device, context);
    const ViewValue pdos = pdos_list(device.rx_pdos, device.tx_pdos, "dev", context);
    const ViewValue dictionary = dictionary_section(device.dictionary(), context);
    const ViewValue dc = dc_section(device, context);
    const ViewValue init_cmds = init_cmds_section(device.mailbox ? &*device.mailbox : nullptr, context);
    const ViewValue modules = modules_section(device, context);

    PageObject o(arena);
    o.add("title", device_title(device, context));
    o.add("name", context.text(device.names));
    o.add("type", device.type.text);
    o.add("product_code_hex", device.type.product_code ? hex(*device.type.product_code, 8) : std::string());
    o.add("revision_hex", device.type.revision_no ? hex(*device.type.revision_no, 8) : std::string());
    const Group* group = device.group_type && context.info ? context.info->find_group(*device.group_type) : nullptr;
    o.add("group_type", device.group_type.value_or(""));
    o.add("group_name", group ? context.text(group->names) : std::string());
    o.add("physics", device.physics);
    o.add("ports", ports_list(device, arena));
    o.add("comment", context.text(device.comments));
    o.add("url", context.text(device.urls));
    o.add("profiles", profiles_text(device));

    Toc toc(arena);
    toc.add(true, "identity", "Device");
    toc.add(is_present(mailbox), "mailbox", "Mailbox");
    toc.add(is_present(sms) || is_present(fmmus), "sync-managers", "SyncManagers and FMMUs");
    toc.add(is_present(images), "process-images", "Process images");
    toc.add(is_present(pdos), "pdos", "PDOs");
    toc.add(is_present(modules), "modules", "Modules and slots");
    toc.add(is_present(dictionary), "dictionary", "Object dictionary");
    toc.add(is_present(dc), "dc", "Distributed clocks");
    toc.add(is_present(init_cmds), "init-cmds", "InitCmds");
    o.add("toc", toc.finish());

    o.add("mailbox", mailbox);
    o.add("has_sync_managers", is_present(sms));
    o.add("sync_managers", sms);
    o.add("has_fmmus", is_present(fmmus));
    o.add("fmmus", fmmus);
    o.add("has_process_images", is_present(images));
    o.add("process_images", images);
    o.add("has_pdos", is_present(pdos));
    o.add("pdos", pdos);
    o.add("modules", modules);
    o.add("dictionary", dictionary);
    o.add("dc", dc);
    o.add("init_cmds", init_cmds);
    return o.finish();
}

namespace {

// A device-shaped object with only a title and the given sections, for files without devices.
ViewValue file_view(const std::string& title, ViewValue dictionary, ViewValue modules, ViewArena& arena) {
    const ViewValue empty = ListBuilder(arena).finish();
    PageObject o(arena);
    o.add("title", title);
    o.add("name", title);
    for (const auto key : {"type", "product_code_hex", "revision_hex", "group_type", "group_name", "physics", "comment", "url", "profiles"})
        o.add(codegen::ViewKey::stored(key), ViewValue::null());
    o.add("ports", empty);
    Toc toc(arena);
    toc.add(is_present(modules), "modules", "Modules");
    toc.add(is_present(dictionary), "dictionary", "Object dictionary");
    o.add("toc", toc.finish());
    o.add("mailbox", ViewValue::null());
    o.add("has_sync_managers", false);
    o.add("sync_managers", empty);
    o.add("has_fmmus", false);
    o.add("fmmus", empty);
    o.add("has_process_images", false);
    o.add("process_images", empty);
    o.add("has_pdos", false);
    o.add("pdos", empty);
    o.add("modules", modules);
    o.add("dictionary", dictionary);
    o.add("dc", ViewValue::null());
    o.add("init_cmds", ViewValue::null());
    return o.finish();
}

}  // namespace

ViewValue dictionary_file_view(const Dictionary& dictionary, const std::string& title, const PageContext& context) {
    return file_view(title, dictionary_section(&dictionary, context), ViewValue::null(), *context.arena);
}

ViewValue module_file_view(const EtherCATInfo& info, const std::string& title, const PageContext& context) {
    return file_view(title, ViewValue::null(), all_modules_section(info, context), *context.arena);
}

}  // namespace esi::doc
