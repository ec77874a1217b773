// process_image.html: the network's process image as pictures. One picture per frame and
// direction (outputs first, as process_image.json lists them), each variable a box at its bit
// offset in the image of its direction, so the rows are numbered as the map's byte offsets are.
// A frame's picture starts at the image's start: the slaves of earlier frames are an elided band
// there, and every offset reads the same in the picture, the table and the map files.

#include "esi/doc/process_image_page.hpp"

#include <algorithm>

#include "doc/markup.hpp"
#include "doc/page_context.hpp"
#include "doc/page_root.hpp"
#include "doc/page_templates.hpp"
#include "doc/process_image_view.hpp"
#include "esi/doc/bit_layout.hpp"
#include "esi/net/network.hpp"
#include "esi/plural.hpp"

namespace esi::doc {

namespace {

// "Axis 1: Outputs.Target position": the variable's name is "<slave>.<module>.<PDO>.<entry>";
// the picture names the slave once, before a colon, and keeps the rest.
std::string box_name(const net::Variable& v, const net::NetworkSlave& slave) {
    const std::string prefix = slave.name + ".";
    const std::string_view rest = std::string_view(v.name).starts_with(prefix) ? std::string_view(v.name).substr(prefix.size()) : v.name;
    return slave.name + ": " + std::string(rest);
}

LayoutField field_of(const net::Variable& v, const net::NetworkSlave& slave) {
    LayoutField f;
    f.name = box_name(v, slave);
    f.bit_offset = v.bit_offset;
    f.bit_size = v.bit_size;
    f.type = v.data_type;
    f.address = v.index == 0 ? std::string() : index_text(v.index, v.subindex);
    f.padding = v.index == 0;
    f.group = static_cast<std::uint32_t>(slave.position);
    return f;
}

ViewValue variable_row(const net::Variable& v, const net::NetworkSlave& slave, const LayoutField& f, ViewArena& arena) {
    PageObject o(arena);
    o.add("name", v.name);
    o.add("label", f.name);
    o.add("slave", slave.name);
    o.add("position", slave.position);
    o.add("pdo", hex(v.pdo_index, 4));
    o.add("pdo_name", v.pdo_name);
    o.add("object", f.address);
    o.add("data_type", v.data_type);
    o.add("bit_size", v.bit_size);
    o.add("byte_offset", v.bit_offset / 8);
    o.add("bit_offset", v.bit_offset % 8);
    o.add("description", field_description(f));
    return o.finish();
}

ViewValue image_view(const net::Network& n, const std::vector<net::Variable>& variables, bool outputs, std::size_t frame, ViewArena& arena) {
    std::vector<const net::Variable*> chosen;
    for (const net::Variable& v : variables)
        if (n.slaves[v.slave].frame == frame) chosen.push_back(&v);
    std::stable_sort(chosen.begin(), chosen.end(), [](const net::Variable* a, const net::Variable* b) { return a->bit_offset < b->bit_offset; });
    std::vector<LayoutField> fields;
    std::uint64_t end_bit = 0;
    ListBuilder rows(arena);
    for (const net::Variable* v : chosen) {
        const net::NetworkSlave& slave = n.slaves[v->slave];
        fields.push_back(field_of(*v, slave));
        end_bit = std::max(end_bit, v->bit_offset + v->bit_size);
        rows.add(variable_row(*v, slave, fields.back(), arena));
    }
    const std::string direction = outputs ? "outputs" : "inputs";
    const bool many_frames = n.image.frames.size() > 1;
    PageObject o(arena);
    const std::string id = std::string(outputs ? "out" : "in") + "-f" + std::to_string(frame);
    o.add("id", id);
    o.add("direction", direction);
    o.add("frame", frame);
    const std::string title = std::string(outputs ? "Outputs (master to slaves)" : "Inputs (slaves to master)") +
                              (many_frames ? ", frame " + std::to_string(frame) : std::string());
    o.add("title", title);
    o.add("bytes", (end_bit + 7) / 8);
    o.add("variable_count", chosen.size());
    o.add("has_variables", !chosen.empty());
    BitLayoutOptions picture;
    picture.id = id;
    picture.title = "Process image of " + n.name + ": " + title + ", byte offsets from the start of the image";
    picture.byte_size = (end_bit + 7) / 8;
    o.add("svg", chosen.empty() ? ViewValue::null() : arena.string(render_bit_layout_svg(fields, picture)));
    o.add("variables", rows.finish());
    return o.finish();
}

ViewValue slave_row(const net::NetworkSlave& s, ViewArena& arena) {
    PageObject o(arena);
    o.add("position", s.position);
    o.add("name", s.name);
    o.add("type", s.device ? s.device->type.text : std::string());
    o.add("station_address", s.phys_addr);
    o.add("byte_offset", s.image_offset);
    o.add("output_bytes", s.output_bytes);
    o.add("input_bytes", s.input_bytes);
    o.add("frame", s.frame);
    return o.finish();
}

}  // namespace

ViewValue process_image_view(ViewArena& arena, const net::Network& n, std::string css) {
    PageObject root(arena);
    PageCommon common;
    common.source_file = n.name;
    common.lang = "en";
    common.css = std::move(css);
    add_common(root, common);
    root.add("network", n.name);
    root.add("master", n.master.name);
    root.add("cycle_time_us", n.master.cycle_time_us);
    root.add("process_data_bytes", n.image.process_data_bytes);
    root.add("frame_count", n.image.frames.size());
    root.add("process_data_text", counted(n.image.process_data_bytes, "byte") + " of process data in " +
                                      counted(n.image.frames.size(), "frame"));
    root.add("logical_base", hex(n.image.logical_base, 8));
    ListBuilder slaves(arena);
    for (const net::NetworkSlave& s : n.slaves) slaves.add(slave_row(s, arena));
    root.add("slaves", slaves.finish());
    ListBuilder images(arena);
    const std::size_t frames = std::max<std::size_t>(n.image.frames.size(), 1);
    for (const bool outputs : {true, false})
        for (std::size_t f = 0; f < frames; ++f) images.add(image_view(n, outputs ? n.image.outputs : n.image.inputs, outputs, f, arena));
    root.add("images", images.finish());
    return root.finish();
}

ProcessImagePage render_process_image_page(const net::Network& network, const std::filesystem::path& output_dir,
                                           const ProcessImagePageOptions& options) {
    ProcessImagePage out;
    std::optional<Template> page = load_page_template("process_image.html.mustache", options.template_dirs, out.diagnostics);
    std::optional<std::string> css = load_stylesheet(options.template_dirs, out.diagnostics);
    if (out.diagnostics.has_errors()) return out;
    ViewArena arena;
    const ViewValue view = process_image_view(arena, network, std::move(*css));
    std::string html;
    page->render(view, html, codegen::mustache::Escape::html);
    out.files.push_back({output_dir / "process_image.html", std::move(html)});
    return out;
}

}  // namespace esi::doc
