// esi-doc's pages: a page per device and an index, rendered from the page templates.

#include "esi/doc/datasheet.hpp"

#include <cctype>
#include <charconv>
#include <map>

#include "doc/markup.hpp"
#include "doc/page_templates.hpp"
#include "doc/page_views.hpp"

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

Datasheets render_datasheets(const EsiDocument& document, const fs::path& output_dir, const DatasheetOptions& options) {
    Datasheets result;
    const PagePlan plan = plan_pages(document, options.device);
    if (plan.empty()) {
        result.diagnostics.emplace(Severity::error, "doc-no-device",
                                   options.device ? "--device matches no device of the file" : "the file describes no device, module or dictionary",
                                   document.path, {});
        return result;
    }

    std::optional<Template> device_template = load_page_template("device.html.mustache", options.template_dirs, result.diagnostics);
    std::optional<Template> index_template = load_page_template("index.html.mustache", options.template_dirs, result.diagnostics);
    std::optional<std::string> css = load_stylesheet(options.template_dirs, result.diagnostics);
    if (result.diagnostics.has_errors()) return result;

    // The index comes last from build_page_views but first in `files`.
    result.files.reserve(plan.devices.size() + plan.extras.size() + 1);
    result.files.push_back({output_dir / "index.html", {}});
    std::size_t last_size = 0;
    build_page_views(document, plan, output_dir, options.lcid, std::move(*css), [&](PageKind kind, const fs::path& file, const ViewValue& root) {
        if (kind == PageKind::index) {
            index_template->render(root, result.files.front().content, codegen::mustache::Escape::html);
            return;
        }
        OutputFile out{file, {}};
        out.content.reserve(last_size + last_size / 8);
        device_template->render(root, out.content, codegen::mustache::Escape::html);
        last_size = out.content.size();
        result.files.push_back(std::move(out));
    });
    return result;
}

}  // namespace esi::doc
