// esi-doc's pages: a page per device and an index, rendered from the page templates.

#include "esi/doc/datasheet.hpp"

#include <cctype>
#include <charconv>
#include <functional>
#include <map>
#include <set>

#include "doc/device_page.hpp"
#include "doc/markup.hpp"
#include "doc/page_root.hpp"
#include "doc/page_templates.hpp"

namespace esi::doc {

namespace fs = std::filesystem;

std::optional<std::uint32_t> parse_language(std::string_view text) {
    if (const auto lcid = lcid_of_language(text)) return lcid;
    std::uint32_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc{} && end == text.data() + text.size() && !text.empty() && value > 0 && value <= 0xFFFF) return value;
    return std::nullopt;
}

std::vector<std::string> page_file_names(const std::vector<const Device*>& devices) {
    std::vector<std::string> out;
    std::map<std::string, int> seen;
    for (const Device* d : devices) {
        std::string stem = slug(d->type.text, "device");
        if (d->type.revision_no) stem += "-rev" + hex(*d->type.revision_no, 8).substr(2);
        // Names compare case-blind: pages must not collide on case-insensitive file systems.
        std::string folded = stem;
        for (char& c : folded) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const int n = ++seen[folded];
        out.push_back(stem + (n > 1 ? "-" + std::to_string(n) : "") + ".html");
    }
    return out;
}

namespace {

struct ExtraPage {
    std::string file;
    std::string title;
    const EtherCATInfo* info = nullptr;        // module file
    const Dictionary* dictionary = nullptr;   // dictionary file
};

PageCommon common_of(const EsiDocument& document, std::uint32_t lcid, std::string css) {
    PageCommon c;
    c.source_file = fs::path(document.path).filename().string();
    c.lang = html_lang(lcid);
    std::set<std::uint32_t> lcids;
    for (const auto& info : document.infos) collect_languages(info, lcids);
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

Datasheets render_datasheets(const EsiDocument& document, const fs::path& output_dir, const DatasheetOptions& options) {
    Datasheets result;
    const std::vector<const Device*> devices = select_devices(document, options.device);
    std::vector<ExtraPage> extras;
    if (!options.device) {
        if (document.dictionary) extras.push_back({"dictionary.html", "Object dictionary", nullptr, &*document.dictionary});
        for (const auto& info : document.infos)
            if (info.devices.empty() && !info.modules.empty()) {
                extras.push_back({"modules.html", "Modules", &info, nullptr});
                break;
            }
    }
    if (devices.empty() && extras.empty()) {
        result.diagnostics.emplace(Severity::error, "doc-no-device",
                                   options.device ? "--device matches no device of the file" : "the file describes no device, module or dictionary",
                                   document.path, {});
        return result;
    }

    std::optional<Template> device_template = load_page_template("device.html.mustache", options.template_dirs, result.diagnostics);
    std::optional<Template> index_template = load_page_template("index.html.mustache", options.template_dirs, result.diagnostics);
    std::optional<std::string> css = load_stylesheet(options.template_dirs, result.diagnostics);
    if (result.diagnostics.has_errors()) return result;

    const PageCommon common = common_of(document, options.lcid, std::move(*css));
    const std::vector<std::string> names = page_file_names(devices);
    result.files.reserve(devices.size() + extras.size() + 1);
    result.files.push_back({output_dir / "index.html", {}});

    ViewArena index_arena;
    ListBuilder index_devices(index_arena);
    PageContext index_context{&index_arena, options.lcid, nullptr};
    std::size_t last_size = 0;
    const auto render_page = [&](const fs::path& file, const std::function<ViewValue(const PageContext&)>& build) {
        ViewArena arena;
        PageContext context{&arena, options.lcid, nullptr};
        PageObject root(arena);
        add_common(root, common);
        root.add("index_href", ViewValue::of_static("index.html"));
        root.add("device", build(context));
        OutputFile out{file, {}};
        out.content.reserve(last_size + last_size / 8);
        device_template->render(root.finish(), out.content, codegen::mustache::Escape::html);
        last_size = out.content.size();
        result.files.push_back(std::move(out));
    };

    for (std::size_t i = 0; i < devices.size(); ++i) {
        const Device& device = *devices[i];
        const EtherCATInfo* info = document.info_of(device);
        render_page(output_dir / names[i], [&](const PageContext& base) {
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
    ListBuilder index_extras(index_arena);
    for (const ExtraPage& page : extras) {
        render_page(output_dir / page.file, [&](const PageContext& context) {
            return page.dictionary ? dictionary_file_view(*page.dictionary, page.title, context)
                                   : module_file_view(*page.info, page.title, context);
        });
        PageObject entry(index_arena);
        entry.add("href", page.file);
        entry.add("title", page.title);
        index_extras.add(entry.finish());
    }

    PageObject root(index_arena);
    add_common(root, common);
    root.add("device_count", devices.size());
    root.add("has_devices", !devices.empty());
    root.add("devices", index_devices.finish());
    root.add("has_extra_pages", !extras.empty());
    root.add("extra_pages", index_extras.finish());
    index_template->render(root.finish(), result.files.front().content, codegen::mustache::Escape::html);
    return result;
}

}  // namespace esi::doc
