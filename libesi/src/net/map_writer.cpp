// process_image.json / .csv / .md: every process-image variable with its slave, PDO,
// index:sub-index, type, direction and place (byte and bit offset in the image of its
// direction) — what a PLC programmer looks up. The three files hold the same rows in the same
// order: outputs, then inputs, each by offset.

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "esi/net/outputs.hpp"

namespace esi::net {

namespace {

struct Row {
    const Variable* v;
    const NetworkSlave* slave;
    const char* direction;
};

std::vector<Row> rows(const Network& n) {
    std::vector<Row> out;
    for (const Variable& v : n.image.outputs) out.push_back({&v, &n.slaves[v.slave], "output"});
    for (const Variable& v : n.image.inputs) out.push_back({&v, &n.slaves[v.slave], "input"});
    return out;
}

// A cell a spreadsheet cannot take for a formula: one starting with = + - @ TAB or CR gets a
// leading apostrophe, as OWASP recommends against CSV injection (docs/esi-net.md); then quoted
// when it holds a separator, a quote or a line break (RFC 4180).
std::string csv_field(const std::string& cell) {
    const bool formula = !cell.empty() && std::string_view("=+-@\t\r").find(cell.front()) != std::string_view::npos;
    const std::string text = formula ? "'" + cell : cell;
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// Text in a Markdown table cell: no pipes, no line breaks, and no raw HTML (Markdown passes
// tags through to the page): < > & are written as character references.
std::string md_cell(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '|') out += "\\|";
        else if (c == '\n' || c == '\r') out += ' ';
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

}  // namespace

std::string write_map_json(const Network& n) {
    nlohmann::ordered_json doc;
    doc["network"] = n.name;
    doc["master"] = n.master.name;
    doc["cycle_time_us"] = n.master.cycle_time_us;
    doc["image_bytes"] = n.image.byte_size;
    doc["process_data_bytes"] = n.image.process_data_bytes;
    nlohmann::ordered_json slaves = nlohmann::ordered_json::array();
    for (const NetworkSlave& s : n.slaves) {
        nlohmann::ordered_json j;
        j["position"] = s.position;
        j["name"] = s.name;
        j["station_address"] = s.phys_addr;
        j["vendor_id"] = fmt::format("0x{:08X}", s.vendor_id);
        j["product_code"] = fmt::format("0x{:08X}", s.product_code);
        j["revision"] = fmt::format("0x{:08X}", s.revision);
        j["type"] = s.device->type.text;
        j["byte_offset"] = s.image_offset;
        j["output_bytes"] = s.output_bytes;
        j["input_bytes"] = s.input_bytes;
        j["frame"] = s.frame;
        slaves.push_back(std::move(j));
    }
    doc["slaves"] = std::move(slaves);
    nlohmann::ordered_json variables = nlohmann::ordered_json::array();
    for (const Row& r : rows(n)) {
        nlohmann::ordered_json j;
        j["name"] = r.v->name;
        j["slave"] = r.slave->name;
        j["position"] = r.slave->position;
        j["direction"] = r.direction;
        j["pdo"] = fmt::format("0x{:04X}", r.v->pdo_index);
        j["pdo_name"] = r.v->pdo_name;
        j["index"] = fmt::format("0x{:04X}", r.v->index);
        j["subindex"] = fmt::format("0x{:02X}", r.v->subindex);
        j["data_type"] = r.v->data_type;
        j["bit_size"] = r.v->bit_size;
        j["byte_offset"] = r.v->bit_offset / 8;
        j["bit_offset"] = r.v->bit_offset % 8;
        j["image_bit_offset"] = r.v->bit_offset;
        variables.push_back(std::move(j));
    }
    doc["variables"] = std::move(variables);
    return doc.dump(2) + "\n";
}

std::string write_map_csv(const Network& n) {
    std::string out = "name,slave,position,direction,pdo,index,subindex,data_type,bit_size,byte_offset,bit_offset\n";
    for (const Row& r : rows(n))
        out += fmt::format("{},{},{},{},0x{:04X},0x{:04X},0x{:02X},{},{},{},{}\n", csv_field(r.v->name), csv_field(r.slave->name),
                           r.slave->position, r.direction, r.v->pdo_index, r.v->index, r.v->subindex, csv_field(r.v->data_type),
                           r.v->bit_size, r.v->bit_offset / 8, r.v->bit_offset % 8);
    return out;
}

std::string write_map_markdown(const Network& n) {
    std::string out = fmt::format("# Process image of {}\n\n", md_cell(n.name));
    out += fmt::format("Master {}, cycle {} µs; {} bytes of process data in {} frame{}.\n\n", md_cell(n.master.name), n.master.cycle_time_us,
                       n.image.process_data_bytes, n.image.frames.size(), n.image.frames.size() == 1 ? "" : "s");
    out += "| # | slave | type | address | byte offset | outputs | inputs |\n|---|---|---|---|---|---|---|\n";
    for (const NetworkSlave& s : n.slaves)
        out += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", s.position, md_cell(s.name), md_cell(s.device->type.text), s.phys_addr,
                           s.image_offset, s.output_bytes, s.input_bytes);
    for (const char* direction : {"output", "input"}) {
        out += fmt::format("\n## {}s\n\n", direction[0] == 'o' ? "Output" : "Input");
        out += "| variable | PDO | object | type | bits | byte | bit |\n|---|---|---|---|---|---|---|\n";
        for (const Row& r : rows(n))
            if (std::string_view(r.direction) == direction)
                out += fmt::format("| {} | 0x{:04X} | 0x{:04X}:{:02X} | {} | {} | {} | {} |\n", md_cell(r.v->name), r.v->pdo_index, r.v->index,
                                   r.v->subindex, md_cell(r.v->data_type), r.v->bit_size, r.v->bit_offset / 8, r.v->bit_offset % 8);
    }
    return out;
}

}  // namespace esi::net
