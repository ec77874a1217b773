// The HTML diff: the change list of a DiffResult (breaking first) and, per device, the process data
// of both files drawn side by side where it differs.

#include "esi/doc/diff_html.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "doc/layout_marks.hpp"
#include "doc/diff_view.hpp"
#include "doc/markup.hpp"
#include "doc/page_root.hpp"
#include "doc/page_templates.hpp"
#include "doc/process_data.hpp"
#include "esi/diff/classification.hpp"
#include "esi/diff/device_groups.hpp"

namespace esi::doc {

namespace {

const Device* find_device(const EsiDocument& document, std::optional<std::uint32_t> product_code, std::optional<std::uint32_t> revision) {
    for (const auto& info : document.infos)
        for (const Device& d : info.devices)
            if (d.type.product_code == product_code && d.type.revision_no == revision) return &d;
    return nullptr;
}

std::string class_css(const Change& c) { return is_error(c.kind) ? "error" : std::string(to_string(c.change_class)); }

std::string line_text(SourcePos pos) { return pos.known() ? std::to_string(pos.line) : "-"; }

ViewValue change_row(const Change& c, ViewArena& arena) {
    PageObject o(arena);
    o.add("class", class_css(c));
    o.add("device", device_heading(c.device));
    o.add("path", c.path.empty() ? std::string(".") : c.path);
    o.add("message", c.message);
    o.add("kind", to_string(c.kind));
    o.add("old_line", line_text(c.old_pos));
    o.add("new_line", line_text(c.new_pos));
    return o.finish();
}

// One picture pair: either side may be absent (an SM or PDO only one file has).
struct PicturePair {
    std::string title;
    std::string id;
    std::vector<LayoutField> old_fields;
    std::vector<LayoutField> new_fields;
    bool has_old = false;
    bool has_new = false;
    std::uint64_t old_bytes = 0;
    std::uint64_t new_bytes = 0;
};

std::uint64_t bytes_of(std::uint64_t bits) { return (bits + 7) / 8; }

void add_pdo_pairs(const Device* old_device, const Device* new_device, PdoDirection direction, std::uint32_t lcid,
                   const std::string& prefix, std::vector<PicturePair>& out) {
    std::map<std::uint32_t, std::pair<const Pdo*, const Pdo*>> by_index;
    if (old_device)
        for (const Pdo& p : old_device->pdos(direction)) by_index[p.index].first = by_index[p.index].first ? by_index[p.index].first : &p;
    if (new_device)
        for (const Pdo& p : new_device->pdos(direction)) by_index[p.index].second = by_index[p.index].second ? by_index[p.index].second : &p;
    const std::string_view element = direction == PdoDirection::rx ? "RxPdo" : "TxPdo";
    for (const auto& [index, sides] : by_index) {
        PicturePair pair;
        const Pdo* named = sides.second ? sides.second : sides.first;
        const std::string& name = localized_text(named->names, lcid);
        pair.title = std::string(element) + " " + hex(index, 4) + (name.empty() ? "" : " " + name);
        pair.id = prefix + (direction == PdoDirection::rx ? "-rx" : "-tx") + hex(index, 4).substr(2);
        if (sides.first) {
            pair.has_old = true;
            pair.old_fields = pdo_fields(*sides.first, lcid);
            pair.old_bytes = bytes_of(sides.first->bit_size());
        }
        if (sides.second) {
            pair.has_new = true;
            pair.new_fields = pdo_fields(*sides.second, lcid);
            pair.new_bytes = bytes_of(sides.second->bit_size());
        }
        out.push_back(std::move(pair));
    }
}

std::vector<PicturePair> picture_pairs(const Device* old_device, const Device* new_device, std::uint32_t lcid, const std::string& prefix) {
    std::vector<PicturePair> out;
    std::map<std::uint32_t, std::pair<std::optional<SmImage>, std::optional<SmImage>>> by_sm;
    if (old_device)
        for (SmImage& image : sm_images(*old_device, lcid)) by_sm[image.sm].first = std::move(image);
    if (new_device)
        for (SmImage& image : sm_images(*new_device, lcid)) by_sm[image.sm].second = std::move(image);
    for (auto& [sm, sides] : by_sm) {
        PicturePair pair;
        pair.title = "Process image of SM" + std::to_string(sm);
        pair.id = prefix + "-sm" + std::to_string(sm);
        if (sides.first) {
            pair.has_old = true;
            pair.old_bytes = bytes_of(sides.first->bit_size);
            pair.old_fields = std::move(sides.first->fields);
        }
        if (sides.second) {
            pair.has_new = true;
            pair.new_bytes = bytes_of(sides.second->bit_size);
            pair.new_fields = std::move(sides.second->fields);
        }
        out.push_back(std::move(pair));
    }
    add_pdo_pairs(old_device, new_device, PdoDirection::rx, lcid, prefix, out);
    add_pdo_pairs(old_device, new_device, PdoDirection::tx, lcid, prefix, out);
    // Only what differs is drawn; a picture both files agree on says nothing about the change.
    std::erase_if(out, [](const PicturePair& p) { return p.has_old && p.has_new && same_layout(p.old_fields, p.new_fields); });
    return out;
}

}  // namespace

ViewValue diff_view(ViewArena& arena, const EsiDocument& old_document, const EsiDocument& new_document, const DiffResult& result,
                    const DiffLabels& labels, std::uint32_t lcid, std::string css) {
    PageObject root(arena);
    PageCommon common;
    common.source_file = std::filesystem::path(labels.new_path).filename().string();
    std::set<std::uint32_t> lcids;
    for (const auto* document : {&old_document, &new_document})
        for (const auto& info : document->infos) collect_languages(info, lcids);
    common.lang = html_lang(page_language(lcid, lcids));
    common.languages = languages_text(lcids);
    common.css = std::move(css);
    add_common(root, common);
    root.add("old_label", labels.old_path);
    root.add("new_label", labels.new_path);
    root.add("verdict", to_string(result.verdict));
    root.add("counts", class_counts(result));
    root.add("identical", result.identical());
    root.add("error_count", result.error_count());
    root.add("has_errors", result.error_count() > 0);

    // The breaking changes and errors of every device, errors first.
    std::vector<const Change*> breaking;
    for (const Change& c : result.changes)
        if (is_error(c.kind) || c.change_class == ChangeClass::breaking) breaking.push_back(&c);
    std::stable_sort(breaking.begin(), breaking.end(), [](const Change* a, const Change* b) { return is_error(a->kind) && !is_error(b->kind); });
    ListBuilder breaking_rows(arena);
    for (const Change* c : breaking) breaking_rows.add(change_row(*c, arena));
    root.add("has_breaking", !breaking.empty());
    root.add("breaking", breaking_rows.finish());

    ListBuilder devices(arena);
    std::size_t group_number = 0;
    for (const DeviceGroup& group : group_by_device(result)) {
        const std::string id = "d" + std::to_string(group_number++);
        PageObject g(arena);
        g.add("id", id);
        g.add("heading", device_heading(*group.device));
        g.add("worst", group.has_error ? std::string("error") : std::string(to_string(group.worst)));
        std::vector<const Change*> changes = group.changes;
        std::stable_sort(changes.begin(), changes.end(), [](const Change* a, const Change* b) {
            if (is_error(a->kind) != is_error(b->kind)) return is_error(a->kind);
            return a->change_class > b->change_class;
        });
        ListBuilder rows(arena);
        for (const Change* c : changes) rows.add(change_row(*c, arena));
        g.add("change_count", changes.size());
        g.add("changes", rows.finish());

        ListBuilder pictures(arena);
        if (const auto& ref = *group.device) {
            const Device* new_device = find_device(new_document, ref->product_code, ref->revision);
            const Device* old_device = find_device(old_document, ref->product_code, ref->compared_revision ? ref->compared_revision : ref->revision);
            for (PicturePair& pair : picture_pairs(old_device, new_device, lcid, id)) {
                mark_changes(pair.old_fields, pair.new_fields);
                PageObject p(arena);
                p.add("id", pair.id);
                p.add("title", pair.title);
                for (const bool is_old : {true, false}) {
                    const bool present = is_old ? pair.has_old : pair.has_new;
                    ViewValue svg = ViewValue::null();
                    if (present) {
                        BitLayoutOptions picture;
                        picture.id = pair.id + (is_old ? "-old" : "-new");
                        picture.title = pair.title + (is_old ? " in " + labels.old_path : " in " + labels.new_path);
                        picture.byte_size = std::max(pair.old_bytes, pair.new_bytes);
                        svg = arena.string(render_bit_layout_svg(is_old ? pair.old_fields : pair.new_fields, picture));
                    }
                    p.add(is_old ? codegen::ViewKey("old_svg") : codegen::ViewKey("new_svg"), svg);
                }
                pictures.add(p.finish());
            }
        }
        g.add("has_pictures", !pictures.empty());
        g.add("pictures", pictures.finish());
        devices.add(g.finish());
    }
    root.add("devices", devices.finish());
    return root.finish();
}

DiffHtml render_diff_html(const EsiDocument& old_document, const EsiDocument& new_document, const DiffResult& result,
                          const DiffLabels& labels, const DiffHtmlOptions& options) {
    DiffHtml out;
    std::optional<Template> page = load_page_template("diff.html.mustache", options.template_dirs, out.diagnostics);
    std::optional<std::string> css = load_stylesheet(options.template_dirs, out.diagnostics);
    if (out.diagnostics.has_errors()) return out;
    ViewArena arena;
    const ViewValue view = diff_view(arena, old_document, new_document, result, labels, options.lcid, std::move(*css));
    page->render(view, out.html, codegen::mustache::Escape::html);
    return out;
}

}  // namespace esi::doc
