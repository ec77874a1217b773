#include "esi/sii/render.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "esi/data_types.hpp"
#include "esi/model/esc_preset.hpp"
#include "esi/model/mailbox_protocol.hpp"
#include "esi/sii/text.hpp"

namespace esi::sii {

namespace {

using Json = nlohmann::ordered_json;

std::string protocols(std::uint16_t bits) { return mailbox_protocol_names(bits, "none"); }

// The PDI type of word 0's low byte by its datasheet name (register 0x0140).
std::string pdi_label(std::uint8_t pdi_control) {
    if (const auto name = pdi_type_name(pdi_control)) return "PDI " + std::string(*name);
    return fmt::format("PDI type 0x{:02X}, not one the ESC datasheets define", pdi_control);
}

template <typename T, std::size_t N>
std::string bit_names(T bits, const std::pair<T, std::string_view> (&names)[N]) {
    std::string out;
    for (const auto& [bit, name] : names)
        if (bits & bit) out += (out.empty() ? "" : ", ") + std::string(name);
    return out.empty() ? "none" : out;
}

constexpr std::pair<std::uint8_t, std::string_view> coe_names[] = {
    {coe_detail::sdo, "SDO"}, {coe_detail::sdo_info, "SDO info"}, {coe_detail::pdo_assign, "PDO assign"},
    {coe_detail::pdo_configuration, "PDO configuration"}, {coe_detail::pdo_upload, "PDO upload"},
    {coe_detail::complete_access, "complete access"}};
constexpr std::pair<std::uint8_t, std::string_view> flag_names[] = {
    {general_flag::enable_safe_op, "enable SafeOp"}, {general_flag::enable_not_lrw, "enable notLRW"},
    {general_flag::mailbox_data_link_layer, "MBoxDataLinkLayer"}, {general_flag::ident_al_status, "IdentALSts"},
    {general_flag::ident_physical_memory, "IdentPhyM"}};
constexpr std::pair<std::uint8_t, std::string_view> enable_names[] = {
    {sm_enable::enable, "enable"}, {sm_enable::fixed_content, "fixed content"}, {sm_enable::virtual_sm, "virtual"},
    {sm_enable::op_only, "OP only"}};
constexpr std::pair<std::uint16_t, std::string_view> pdo_flag_names[] = {
    {pdo_flag::mandatory, "mandatory"}, {pdo_flag::default_assigned, "default"}, {pdo_flag::oversample, "oversample"},
    {pdo_flag::fixed_content, "fixed"}, {pdo_flag::virtual_content, "virtual"}, {pdo_flag::download_anyway, "download anyway"},
    {pdo_flag::from_module, "from module"}, {pdo_flag::module_align, "module align"}, {pdo_flag::depend_on_slot, "depend on slot"},
    {pdo_flag::depend_on_slot_group, "depend on slot group"}, {pdo_flag::overwritten_by_module, "overwritten by module"}};

std::string_view port_name(std::uint8_t code) {
    switch (code) {
        case port_type::none: return "none";
        case port_type::mii: return "MII";
        case port_type::reserved: return "reserved";
        case port_type::ebus: return "EBUS";
        case port_type::fast_hot_connect: return "fast hot connect";
        default: return "unknown";
    }
}

std::string_view fmmu_name(std::uint8_t code) {
    switch (code) {
        case fmmu_usage::unused:
        case fmmu_usage::unused_ff: return "not used";
        case fmmu_usage::outputs: return "Outputs";
        case fmmu_usage::inputs: return "Inputs";
        case fmmu_usage::sync_manager_status: return "MBoxState";
        default: return "unknown";
    }
}

std::string_view sm_type_name(std::uint8_t code) {
    switch (code) {
        case sm_type::unused: return "unused";
        case sm_type::mailbox_out: return "MBoxOut";
        case sm_type::mailbox_in: return "MBoxIn";
        case sm_type::outputs: return "Outputs";
        case sm_type::inputs: return "Inputs";
        default: return "unknown";
    }
}

std::string data_type_name(std::uint8_t code) {
    if (code == 0) return "none";
    if (const BasicType* t = find_basic_type_by_code(code)) return std::string(t->esi_name);
    return "unknown";
}

std::string hex_bytes(const std::vector<std::uint8_t>& bytes) {
    std::string out;
    out.reserve(bytes.size() * 2);
    for (const std::uint8_t b : bytes) out += fmt::format("{:02X}", b);
    return out;
}

// Control characters and quotes escaped, so a hostile string cannot break the text layout.
std::string display_text(std::string_view bytes) {
    std::string out = "\"";
    for (const char c : sii_text_to_utf8(bytes)) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (u < 0x20 || u == 0x7F) {
            out += fmt::format("\\x{:02X}", u);
        } else {
            out += c;
        }
    }
    return out + "\"";
}

class TextDump {
public:
    explicit TextDump(const DecodedImage& d) : d_(d), image_(d.image) {}

    std::string run(std::string_view path) {
        line("{}: {} bytes, EEPROM {} bytes (word 0x3E = 0x{:04X}), version {}", path, d_.byte_count,
             image_.header.eeprom_bytes(), image_.header.size, image_.header.version);
        if (d_.header_complete) header();
        else line("Header incomplete: {} of {} bytes", d_.byte_count, header_bytes);
        if (d_.header_complete) categories();
        faults();
        return std::move(out_);
    }

private:
    template <typename... Args>
    void line(fmt::format_string<Args...> f, Args&&... args) {
        out_ += fmt::format(f, std::forward<Args>(args)...);
        out_ += '\n';
    }
    std::string str(std::uint8_t index) const {
        if (index == 0) return "0";
        const auto s = image_.string_at(index);
        return s ? fmt::format("{} {}", index, display_text(*s)) : fmt::format("{} (no such string)", index);
    }

    void header() {
        const Header& h = image_.header;
        line("Header");
        line("  0x00 PDI control               0x{:04X} ({})", h.config_word(0), pdi_label(h.config_data[0]));
        line("  0x01 PDI configuration         0x{:04X}", h.config_word(1));
        line("  0x02 SYNC impulse length       0x{:04X} ({} ns)", h.config_word(2), 10u * h.config_word(2));
        line("  0x03 PDI configuration 2       0x{:04X}", h.config_word(3));
        line("  0x04 configured station alias  0x{:04X}", h.config_word(4));
        line("  0x05 reserved                  0x{:04X}", h.config_word(5));
        line("  0x06 reserved                  0x{:04X}", h.config_word(6));
        if (h.checksum == crc_disabled_marker)
            line("  0x07 checksum                  0x{:04X} (CRC check disabled)", h.checksum);
        else
            line("  0x07 checksum                  0x{:04X} (CRC-8 of words 0-6 is 0x{:02X}: {})", h.checksum, d_.computed_crc,
                 d_.crc_ok ? "ok" : "MISMATCH");
        line("  0x08 vendor id                 0x{:08X}", h.vendor_id);
        line("  0x0A product code              0x{:08X}", h.product_code);
        line("  0x0C revision                  0x{:08X}", h.revision_no);
        line("  0x0E serial number             0x{:08X}", h.serial_no);
        line("  0x10 execution delay           0x{:04X}", h.execution_delay);
        line("  0x11 port 0 delay              0x{:04X}", h.port0_delay);
        line("  0x12 port 1 delay              0x{:04X}", h.port1_delay);
        line("  0x13 reserved                  0x{:04X}", h.reserved_0x13);
        line("  0x14 bootstrap receive mailbox 0x{:04X}, {} bytes", h.bootstrap_receive_offset, h.bootstrap_receive_size);
        line("  0x16 bootstrap send mailbox    0x{:04X}, {} bytes", h.bootstrap_send_offset, h.bootstrap_send_size);
        line("  0x18 standard receive mailbox  0x{:04X}, {} bytes", h.standard_receive_offset, h.standard_receive_size);
        line("  0x1A standard send mailbox     0x{:04X}, {} bytes", h.standard_send_offset, h.standard_send_size);
        line("  0x1C mailbox protocols         0x{:04X} ({})", h.mailbox_protocols, protocols(h.mailbox_protocols));
        std::string reserved;
        for (std::size_t i = 0; i < h.reserved_0x1d.size(); ++i)
            if (h.reserved_0x1d[i] != 0) reserved += fmt::format(" 0x{:02X}=0x{:04X}", 0x1D + i, h.reserved_0x1d[i]);
        line("  0x1D-0x3D reserved             {}", reserved.empty() ? "all 0" : "non-zero:" + reserved);
        line("  0x3E size                      0x{:04X} ({} bytes)", h.size, h.eeprom_bytes());
        line("  0x3F version                   {}", h.version);
    }

    void categories() {
        line("Categories");
        for (const auto& c : image_.categories) {
            line("  0x{:04X} {} ({}), {} words", c.offset, category_name(c.type), c.type, c.declared_words);
            std::visit([&](const auto& content) { body(content); }, c.content);
        }
        if (d_.end_offset) line("  0x{:04X} end marker", *d_.end_offset);
    }

    void body(const RawData& raw) {
        for (std::size_t at = 0; at < raw.bytes.size(); at += 16) {
            std::string row;
            for (std::size_t i = at; i < raw.bytes.size() && i < at + 16; ++i) row += fmt::format(" {:02X}", raw.bytes[i]);
            line("     {}", row);
        }
    }
    void body(const Strings& s) {
        line("      {} strings", s.items.size());
        for (std::size_t i = 0; i < s.items.size(); ++i) line("      {:3} {}", i + 1, display_text(s.items[i]));
    }
    void body(const General& g) {
        line("      group {}, image {}, order {}, name {}", str(g.group_idx), str(g.image_idx), str(g.order_idx), str(g.name_idx));
        line("      byte 4 (reserved) 0x{:02X}", g.reserved_4);
        line("      CoE details 0x{:02X} ({})", g.coe_details, bit_names(g.coe_details, coe_names));
        line("      FoE details 0x{:02X}, EoE details 0x{:02X}, SoE channels {}, DS402 channels {}, SysmanClass {}", g.foe_details,
             g.eoe_details, g.soe_channels, g.ds402_channels, g.sysman_class);
        line("      flags 0x{:02X} ({})", g.flags, bit_names(g.flags, flag_names));
        line("      CurrentOnEBus {} mA", g.current_on_ebus);
        line("      byte 14 (group index) {}", g.group_idx_duplicate);
        line("      physical ports 0x{:04X}: 0 {}, 1 {}, 2 {}, 3 {}", g.physical_ports, port_name(g.port(0)), port_name(g.port(1)),
             port_name(g.port(2)), port_name(g.port(3)));
        line("      physical memory address 0x{:04X}", g.physical_memory_address);
    }
    void body(const Fmmus& f) {
        for (std::size_t i = 0; i < f.usages.size(); ++i) line("      FMMU{} 0x{:02X} {}", i, f.usages[i], fmmu_name(f.usages[i]));
    }
    void body(const SyncManagers& s) {
        for (std::size_t i = 0; i < s.items.size(); ++i) {
            const auto& sm = s.items[i];
            line("      SM{} start 0x{:04X}, length {}, control 0x{:02X}, status 0x{:02X}, enable 0x{:02X} ({}), type {} ({})", i,
                 sm.start_address, sm.length, sm.control, sm.status, sm.enable, bit_names(sm.enable, enable_names), sm.type,
                 sm_type_name(sm.type));
        }
    }
    void body(const Pdos& p) {
        for (const auto& pdo : p.items) {
            line("      PDO 0x{:04X} name {}: SM {}, DC sync {}, flags 0x{:04X} ({}), {} entries", pdo.index, str(pdo.name_idx),
                 pdo.sync_manager == pdo_no_sync_manager ? std::string("none") : std::to_string(pdo.sync_manager), pdo.dc_sync,
                 pdo.flags, bit_names(pdo.flags, pdo_flag_names), pdo.entries.size());
            for (const auto& e : pdo.entries)
                line("        0x{:04X}:{:02X} name {}, type 0x{:02X} ({}), {} bits, flags 0x{:04X}", e.index, e.subindex,
                     str(e.name_idx), e.data_type, data_type_name(e.data_type), e.bit_len, e.flags);
        }
    }
    void body(const DcOpModes& d) {
        for (std::size_t i = 0; i < d.items.size(); ++i) {
            const auto& m = d.items[i];
            line("      op mode {} name {}, desc {}: AssignActivate 0x{:04X}", i, str(m.name_idx), str(m.desc_idx), m.assign_activate);
            line("        cycle time SYNC0 {} ns (factor {}), shift SYNC0 {} ns, shift SYNC1 {} ns, SYNC1 factor {}", m.cycle_time0,
                 m.sync0_cycle_factor, static_cast<std::int32_t>(m.shift_time0), static_cast<std::int32_t>(m.shift_time1),
                 m.sync1_cycle_factor);
        }
    }

    void faults() {
        if (d_.faults.empty()) {
            line("Faults: none");
            return;
        }
        line("Faults: {} errors, {} warnings", d_.count(Severity::error), d_.count(Severity::warning));
        for (const auto& f : d_.faults) line("  0x{:04X} {}: {} [{}]", f.offset, to_string(f.severity), f.message, f.rule);
    }

    const DecodedImage& d_;
    const Image& image_;
    std::string out_;
};

Json string_ref(const Image& image, std::uint8_t index) {
    Json j;
    j["index"] = index;
    const auto s = image.string_at(index);
    j["text"] = s ? Json(sii_text_to_utf8(*s)) : Json(nullptr);
    return j;
}

Json content_json(const Image& image, const CategoryContent& content) {
    struct Visitor {
        const Image& image;
        Json operator()(const RawData& raw) const { return Json{{"data", hex_bytes(raw.bytes)}}; }
        Json operator()(const Strings& s) const {
            Json list = Json::array();
            for (const auto& item : s.items) list.push_back(sii_text_to_utf8(item));
            return Json{{"strings", list}};
        }
        Json operator()(const General& g) const {
            Json ports = Json::array();
            for (unsigned p = 0; p < 4; ++p) ports.push_back(Json{{"port", p}, {"type", g.port(p)}, {"name", port_name(g.port(p))}});
            Json j;
            j["group"] = string_ref(image, g.group_idx);
            j["image"] = string_ref(image, g.image_idx);
            j["order"] = string_ref(image, g.order_idx);
            j["name"] = string_ref(image, g.name_idx);
            j["reserved_4"] = g.reserved_4;
            j["coe_details"] = g.coe_details;
            j["foe_details"] = g.foe_details;
            j["eoe_details"] = g.eoe_details;
            j["soe_channels"] = g.soe_channels;
            j["ds402_channels"] = g.ds402_channels;
            j["sysman_class"] = g.sysman_class;
            j["flags"] = g.flags;
            j["current_on_ebus"] = g.current_on_ebus;
            j["group_index_byte14"] = g.group_idx_duplicate;
            j["physical_ports"] = g.physical_ports;
            j["ports"] = ports;
            j["physical_memory_address"] = g.physical_memory_address;
            return j;
        }
        Json operator()(const Fmmus& f) const {
            Json list = Json::array();
            for (const std::uint8_t u : f.usages) list.push_back(Json{{"usage", u}, {"name", fmmu_name(u)}});
            return Json{{"fmmus", list}};
        }
        Json operator()(const SyncManagers& s) const {
            Json list = Json::array();
            for (const auto& sm : s.items)
                list.push_back(Json{{"start_address", sm.start_address}, {"length", sm.length}, {"control", sm.control},
                                    {"status", sm.status}, {"enable", sm.enable}, {"type", sm.type}, {"type_name", sm_type_name(sm.type)}});
            return Json{{"sync_managers", list}};
        }
        Json operator()(const Pdos& p) const {
            Json list = Json::array();
            for (const auto& pdo : p.items) {
                Json entries = Json::array();
                for (const auto& e : pdo.entries)
                    entries.push_back(Json{{"index", e.index}, {"subindex", e.subindex}, {"name", string_ref(image, e.name_idx)},
                                           {"data_type", e.data_type}, {"data_type_name", data_type_name(e.data_type)},
                                           {"bit_len", e.bit_len}, {"flags", e.flags}});
                list.push_back(Json{{"index", pdo.index}, {"sync_manager", pdo.sync_manager}, {"dc_sync", pdo.dc_sync},
                                    {"name", string_ref(image, pdo.name_idx)}, {"flags", pdo.flags}, {"entries", entries}});
            }
            return Json{{"pdos", list}};
        }
        Json operator()(const DcOpModes& d) const {
            Json list = Json::array();
            for (const auto& m : d.items)
                list.push_back(Json{{"name", string_ref(image, m.name_idx)}, {"desc", string_ref(image, m.desc_idx)},
                                    {"assign_activate", m.assign_activate}, {"cycle_time0", m.cycle_time0},
                                    {"shift_time0", static_cast<std::int32_t>(m.shift_time0)},
                                    {"shift_time1", static_cast<std::int32_t>(m.shift_time1)},
                                    {"sync0_cycle_factor", m.sync0_cycle_factor}, {"sync1_cycle_factor", m.sync1_cycle_factor}});
            return Json{{"op_modes", list}};
        }
    };
    return std::visit(Visitor{image}, content);
}

}  // namespace

std::string render_dump_text(const DecodedImage& image, std::string_view path) { return TextDump(image).run(path); }

std::string render_dump_json(const DecodedImage& d, std::string_view path) {
    const Image& image = d.image;
    const Header& h = image.header;
    Json j;
    j["path"] = std::string(path);
    j["bytes"] = d.byte_count;
    j["header_complete"] = d.header_complete;
    if (d.header_complete) {
        Json header;
        Json config = Json::array();
        for (std::size_t i = 0; i < 7; ++i) config.push_back(h.config_word(i));
        header["config_words"] = config;
        header["pdi_control"] = h.config_word(0);
        header["pdi_type"] = pdi_label(h.config_data[0]);
        header["pdi_configuration"] = h.config_word(1);
        header["sync_impulse_length"] = h.config_word(2);
        header["pdi_configuration2"] = h.config_word(3);
        header["station_alias"] = h.config_word(4);
        header["checksum"] = h.checksum;
        header["crc"] = Json{{"computed", d.computed_crc}, {"ok", d.crc_ok}, {"disabled", h.checksum == crc_disabled_marker}};
        header["vendor_id"] = h.vendor_id;
        header["product_code"] = h.product_code;
        header["revision_no"] = h.revision_no;
        header["serial_no"] = h.serial_no;
        header["execution_delay"] = h.execution_delay;
        header["port0_delay"] = h.port0_delay;
        header["port1_delay"] = h.port1_delay;
        header["bootstrap_mailbox"] = Json{{"receive_offset", h.bootstrap_receive_offset}, {"receive_size", h.bootstrap_receive_size},
                                           {"send_offset", h.bootstrap_send_offset}, {"send_size", h.bootstrap_send_size}};
        header["standard_mailbox"] = Json{{"receive_offset", h.standard_receive_offset}, {"receive_size", h.standard_receive_size},
                                          {"send_offset", h.standard_send_offset}, {"send_size", h.standard_send_size}};
        header["mailbox_protocols"] = h.mailbox_protocols;
        header["mailbox_protocol_names"] = protocols(h.mailbox_protocols);
        Json reserved = Json::object();
        for (std::size_t i = 0; i < h.reserved_0x1d.size(); ++i)
            if (h.reserved_0x1d[i] != 0) reserved[fmt::format("0x{:02X}", 0x1D + i)] = h.reserved_0x1d[i];
        header["reserved_nonzero"] = reserved;
        header["size_word"] = h.size;
        header["eeprom_bytes"] = h.eeprom_bytes();
        header["version"] = h.version;
        j["header"] = header;
    }
    Json categories = Json::array();
    for (const auto& c : image.categories) {
        Json cj;
        cj["offset"] = c.offset;
        cj["type"] = c.type;
        cj["name"] = category_name(c.type);
        cj["words"] = c.declared_words;
        cj["content"] = content_json(image, c.content);
        categories.push_back(cj);
    }
    j["categories"] = categories;
    j["end_offset"] = d.end_offset ? Json(*d.end_offset) : Json(nullptr);
    Json faults = Json::array();
    for (const auto& f : d.faults)
        faults.push_back(Json{{"offset", f.offset}, {"severity", to_string(f.severity)}, {"rule", f.rule}, {"message", f.message}});
    j["faults"] = faults;
    j["summary"] = Json{{"errors", d.count(Severity::error)}, {"warnings", d.count(Severity::warning)}, {"infos", d.count(Severity::info)}};
    return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string render_faults_text(const DecodedImage& image, std::string_view path) {
    std::string out;
    for (const auto& f : image.faults)
        out += fmt::format("{}: byte 0x{:04X}: {}: {} [{}]\n", path, f.offset, to_string(f.severity), f.message, f.rule);
    return out;
}

std::string render_diagnostics_text(const Diagnostics& diagnostics) {
    std::string out;
    for (const auto& d : diagnostics) out += format_diagnostic(d);
    return out;
}

std::string render_check_text(const DecodedImage& image, std::string_view image_path, const Diagnostics& mismatches,
                              std::string_view device_label) {
    std::string out = render_faults_text(image, image_path);
    out += render_diagnostics_text(mismatches);
    const std::size_t errors = image.count(Severity::error) + mismatches.count(Severity::error);
    const std::size_t warnings = image.count(Severity::warning) + mismatches.count(Severity::warning);
    out += fmt::format("{} vs {}: {} ({} errors, {} warnings)\n", image_path, device_label,
                       errors == 0 ? "consistent" : "MISMATCH", errors, warnings);
    return out;
}

}  // namespace esi::sii
