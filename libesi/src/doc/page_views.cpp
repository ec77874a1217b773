#include "doc/page_views.hpp"

#include <algorithm>
#include <set>

#include "doc/device_page.hpp"
#include "doc/markup.hpp"
#include "doc/page_root.hpp"
#include "esi/doc/datasheet.hpp"
#include "esi/plural.hpp"

namespace esi::doc {

namespace fs = std::filesystem;

namespace {

PageCommon common_of(const EsiDocument& document, std::uint32_t lcid, std::string css) {
    PageCommon c;
    c.source_file = fs::path(document.path).filename().string();
    std::set<std::uint32_t> lcids;
    for (const auto& info : document.infos) collect_languages(info, lcids);
    c.lang = html_lang(page_language(lcid, lcids));
    c.languages = languages_text(lcids);
    c.css = std::move(css);
    for (const auto& info : document.infos)
        if (info.vendor) {
            c.vendor_name = localized_text(info.vendor->names, lcid);
            if (info.vendor->id) c.vendor_id_hex = hex(*info.vendor->id, 8);
            break;
        }
    return c;
}

}  // namespace

PagePlan plan_pages(const EsiDocument& document, const std::optional<DeviceSelector>& device) {
    PagePlan plan;
    plan.devices = select_devices(document, device);
    if (!device) {
        if (document.dictionary) plan.extras.push_back({"dictionary.html", "Object dictionary", nullptr, &*document.dictionary});
        for (const auto& info : document.infos)
            if (info.devices.empty() && !info.modules.empty()) {
                plan.extras.push_back({"modules.html", "Modules", &info, nullptr});
                break;
            }
    }
    return plan;
}

void build_page_views(const EsiDocument& document, const PagePlan& plan, const fs::path& output_dir, std::uint32_t lcid, std::string css,
                      const PageSink& sink) {
    const PageCommon common = common_of(document, lcid, std::move(css));
    const std::vector<std::string> names = page_file_names(plan.devices);

    ViewArena index_arena;
    ListBuilder index_devices(index_arena);
    PageContext index_context{&index_arena, lcid, nullptr};
    const auto page = [&](const fs::path& file, const std::function<ViewValue(const PageContext&)>& build) {
        ViewArena arena;
        PageContext context{&arena, lcid, nullptr};
        PageObject root(arena);
        add_common(root, common);
        root.add("index_href", ViewValue::of_static("index.html"));
        root.add("device", build(context));
        sink(PageKind::device, file, root.finish());
    };

    for (std::size_t i = 0; i < plan.devices.size(); ++i) {
        const Device& device = *plan.devices[i];
        const EtherCATInfo* info = document.info_of(device);
        page(output_dir / names[i], [&](const PageContext& base) {
            PageContext context = base;
            context.info = info;
            return device_view(device, context);
        });
        index_context.info = info;
        PageObject entry(index_arena);
        entry.add("href", names[i]);
        entry.add("title", device_title(device, index_context));
        entry.add("name", index_context.text(device.names));
        entry.add("type", device.type.text);
        entry.add("product_code_hex", device.type.product_code ? hex(*device.type.product_code, 8) : std::string());
        entry.add("revision_hex", device.type.revision_no ? hex(*device.type.revision_no, 8) : std::string());
        const Group* group = device.group_type && info ? info->find_group(*device.group_type) : nullptr;
        entry.add("group_name", group ? index_context.text(group->names) : device.group_type.value_or(""));
        index_devices.add(entry.finish());
    }
    // The catalogue is what its groups are called ("Digital I/O, Analog inputs"), in the order
    // the devices use them; the title names vendor and catalogue, not the file (issue 23).
    std::vector<std::string> catalogue_groups;
    for (const Device* device : plan.devices) {
        const EtherCATInfo* info = document.info_of(*device);
        const Group* group = device->group_type && info ? info->find_group(*device->group_type) : nullptr;
        index_context.info = info;
        const std::string name = group ? index_context.text(group->names) : device->group_type.value_or("");
        if (!name.empty() && std::find(catalogue_groups.begin(), catalogue_groups.end(), name) == catalogue_groups.end())
            catalogue_groups.push_back(name);
    }
    std::string catalogue;
    for (std::size_t i = 0; i < catalogue_groups.size() && i < 3; ++i) catalogue += (i ? ", " : "") + catalogue_groups[i];
    if (catalogue_groups.size() > 3) catalogue += " …";
    // A file without devices (a dictionary or module file) is what its pages are.
    if (catalogue.empty())
        for (const ExtraPage& extra : plan.extras) catalogue += (catalogue.empty() ? "" : ", ") + extra.title;
    ListBuilder index_extras(index_arena);
    for (const ExtraPage& extra : plan.extras) {
        page(output_dir / extra.file, [&](const PageContext& context) {
            return extra.dictionary ? dictionary_file_view(*extra.dictionary, extra.title, context)
                                    : module_file_view(*extra.info, extra.title, context);
        });
        PageObject entry(index_arena);
        entry.add("href", extra.file);
        entry.add("title", extra.title);
        index_extras.add(entry.finish());
    }

    PageObject root(index_arena);
    add_common(root, common);
    root.add("device_count", plan.devices.size());
    root.add("device_count_text", counted(plan.devices.size(), "device page"));
    root.add("catalogue", catalogue);
    std::string title = common.vendor_name;
    if (!catalogue.empty()) title += (title.empty() ? "" : ": ") + catalogue;
    root.add("title", title.empty() ? common.source_file : title);
    root.add("has_devices", !plan.devices.empty());
    root.add("devices", index_devices.finish());
    root.add("has_extra_pages", !plan.extras.empty());
    root.add("extra_pages", index_extras.finish());
    sink(PageKind::index, output_dir / "index.html", root.finish());
}

}  // namespace esi::doc
