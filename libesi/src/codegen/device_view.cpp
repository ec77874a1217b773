// One device in the view: identity, SyncManagers, FMMUs, mailbox, DC, EEPROM/ESC settings, PDOs,
// the default process images and the object dictionary.

#include <algorithm>
#include <cctype>
#include <map>

#include "codegen/values.hpp"
#include "codegen/view_parts.hpp"
#include "esi/codegen/identifier.hpp"

namespace esi::codegen {

void ViewContext::warn(std::string rule, std::string message, SourcePos pos) const {
    if (diagnostics) diagnostics->emplace(Severity::warning, std::move(rule), std::move(message), path, pos);
}

namespace {

Json optional_number(const std::optional<std::uint32_t>& value) { return value ? Json(*value) : Json(nullptr); }

std::string lower(std::string_view text) {
    std::string out(trim(text));
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

// The SM's job from its text (ETG.2000 SmType: MBoxOut, MBoxIn, Outputs, Inputs).
std::string sm_role(const SyncManager& sm) {
    const std::string t = lower(sm.type);
    if (t == "mboxout") return "mailbox_out";
    if (t == "mboxin") return "mailbox_in";
    if (t == "outputs") return "outputs";
    if (t == "inputs") return "inputs";
    return "other";
}

// SII SyncM category type byte (ETG.2010): 0 unused, 1 mailbox out, 2 mailbox in, 3 outputs, 4 inputs.
int role_code(const std::string& role) {
    if (role == "mailbox_out") return 1;
    if (role == "mailbox_in") return 2;
    if (role == "outputs") return 3;
    if (role == "inputs") return 4;
    return 0;
}

Json sm_view(const SyncManager& sm, std::size_t number) {
    Json j;
    j["present"] = true;
    j["number"] = number;
    j["type"] = sm.type;
    j["role"] = sm_role(sm);
    j["role_code"] = role_code(sm_role(sm));
    j["start_address"] = optional_number(sm.start_address);
    j["start_address_hex"] = hex(sm.start_address.value_or(0), 4);
    j["default_size"] = optional_number(sm.default_size);
    j["min_size"] = optional_number(sm.min_size);
    j["max_size"] = optional_number(sm.max_size);
    // ESC register 0x0804+8n: ControlByte; bit 6 enables the watchdog trigger.
    j["control_byte"] = optional_number(sm.control_byte);
    j["control_byte_hex"] = hex(sm.control_byte.value_or(0), 2);
    j["watchdog_trigger"] = (sm.control_byte.value_or(0) & 0x40u) != 0;
    j["enable"] = optional_number(sm.enable);
    j["enabled"] = sm.enable.value_or(0) != 0;
    j["virtual"] = sm.is_virtual.value_or(false);
    return j;
}

Json absent_sm() {
    Json j;
    j["present"] = false;
    j["number"] = nullptr;
    j["type"] = "";
    j["role"] = "";
    j["role_code"] = 0;
    j["start_address"] = nullptr;
    j["start_address_hex"] = hex(0, 4);
    j["default_size"] = nullptr;
    j["min_size"] = nullptr;
    j["max_size"] = nullptr;
    j["control_byte"] = nullptr;
    j["control_byte_hex"] = hex(0, 2);
    j["watchdog_trigger"] = false;
    j["enable"] = nullptr;
    j["enabled"] = false;
    j["virtual"] = false;
    return j;
}

Json first_sm_with_role(const Device& device, std::string_view role) {
    for (std::size_t n = 0; n < device.sms.size(); ++n)
        if (sm_role(device.sms[n]) == role) return sm_view(device.sms[n], n);
    return absent_sm();
}

Json init_cmd_view(const InitCmd& cmd, std::string_view protocol) {
    Json j;
    j["protocol"] = std::string(protocol);
    Json transitions = Json::array();
    std::string text;
    for (const auto& t : cmd.transitions) {
        transitions.push_back(Json{{"name", t.text}});
        text += (text.empty() ? "" : " ") + t.text;
    }
    j["transitions"] = std::move(transitions);
    j["transitions_text"] = text;
    j["has_index"] = cmd.index.has_value();
    j["index"] = optional_number(cmd.index);
    j["index_hex"] = hex(cmd.index.value_or(0), 4);
    j["subindex"] = optional_number(cmd.subindex);
    j["subindex_hex"] = hex(cmd.subindex.value_or(0), 2);
    const auto bytes = cmd.data.bytes();
    Json data = Json::array();
    std::string literal;
    if (bytes)
        for (const auto b : *bytes) data.push_back(Json{{"hex", hex(b, 2)}});
    j["data_hex"] = cmd.data.text;
    j["data"] = std::move(data);
    j["data_literal"] = c_string_literal(bytes ? std::string(bytes->begin(), bytes->end()) : std::string());
    j["byte_count"] = bytes ? bytes->size() : 0;
    j["complete_access"] = cmd.complete_access.value_or(false);
    j["comment"] = c_comment_text(cmd.comment.value_or(""));
    return j;
}

Json mailbox_view(const Device& device) {
    Json j;
    const Mailbox* mb = device.mailbox ? &*device.mailbox : nullptr;
    j["present"] = mb != nullptr;
    j["out"] = first_sm_with_role(device, "mailbox_out");
    j["in"] = first_sm_with_role(device, "mailbox_in");
    Json protocols;
    protocols["aoe"] = mb && mb->aoe.has_value();
    protocols["eoe"] = mb && mb->eoe.has_value();
    protocols["coe"] = mb && mb->coe.has_value();
    protocols["foe"] = mb && mb->foe.has_value();
    protocols["soe"] = mb && mb->soe.has_value();
    protocols["voe"] = mb && mb->voe.has_value();
    j["protocols"] = std::move(protocols);
    const std::uint16_t bits = mb ? mb->protocol_bits() : 0;
    j["protocol_bits"] = bits;
    j["protocol_bits_hex"] = hex(bits, 4);
    j["data_link_layer"] = mb && mb->data_link_layer.value_or(false);

    Json coe;
    const CoeProtocol* c = mb && mb->coe ? &*mb->coe : nullptr;
    coe["sdo_info"] = c && c->sdo_info.value_or(false);
    coe["pdo_assign"] = c && c->pdo_assign.value_or(false);
    coe["pdo_config"] = c && c->pdo_config.value_or(false);
    coe["pdo_upload"] = c && c->pdo_upload.value_or(false);
    coe["complete_access"] = c && c->complete_access.value_or(false);
    coe["segmented_sdo"] = c && c->segmented_sdo.value_or(false);
    j["coe"] = std::move(coe);

    Json init_cmds = Json::array();
    if (mb) {
        if (mb->coe)
            for (const auto& cmd : mb->coe->init_cmds) init_cmds.push_back(init_cmd_view(cmd, "CoE"));
        if (mb->soe)
            for (const auto& cmd : mb->soe->init_cmds) init_cmds.push_back(init_cmd_view(cmd, "SoE"));
        if (mb->eoe)
            for (const auto& cmd : mb->eoe->init_cmds) init_cmds.push_back(init_cmd_view(cmd, "EoE"));
        if (mb->aoe)
            for (const auto& cmd : mb->aoe->init_cmds) init_cmds.push_back(init_cmd_view(cmd, "AoE"));
    }
    j["init_cmds"] = std::move(init_cmds);

    // Eeprom/BootStrap: bootstrap mailbox out offset, out size, in offset, in size (little-endian
    // words), the values SII words 0x14..0x17 carry (ETG.2010).
    Json boot;
    std::optional<std::vector<std::uint8_t>> raw;
    if (device.eeprom && device.eeprom->boot_strap) raw = device.eeprom->boot_strap->bytes();
    const bool has_boot = raw && raw->size() >= 8;
    auto word = [&](std::size_t k) -> std::uint32_t { return has_boot ? (*raw)[2 * k] | ((*raw)[2 * k + 1] << 8) : 0; };
    boot["present"] = has_boot;
    boot["out_start_address"] = word(0);
    boot["out_start_address_hex"] = hex(word(0), 4);
    boot["out_size"] = word(1);
    boot["in_start_address"] = word(2);
    boot["in_start_address_hex"] = hex(word(2), 4);
    boot["in_size"] = word(3);
    j["bootstrap"] = std::move(boot);
    return j;
}

Json dc_time(const std::optional<DcTime>& t) {
    Json j;
    j["present"] = t.has_value();
    j["value"] = t ? t->value : 0;
    j["factor"] = t && t->factor ? Json(*t->factor) : Json(nullptr);
    return j;
}

Json dc_view(const Device& device) {
    Json j;
    j["present"] = device.dc.has_value() && !device.dc->op_modes.empty();
    Json modes = Json::array();
    if (device.dc) {
        IdentifierScope scope;
        for (const auto& m : device.dc->op_modes) {
            Json mode;
            mode["name"] = m.name;
            mode["c_name"] = scope.claim(c_identifier(m.name, "op_mode"));
            mode["name_literal"] = c_string_literal(m.name);
            mode["description"] = m.desc.value_or("");
            mode["description_literal"] = c_string_literal(m.desc.value_or(""));
            mode["assign_activate"] = m.assign_activate;
            mode["assign_activate_hex"] = hex(m.assign_activate, 4);
            mode["cycle_time_sync0"] = dc_time(m.cycle_time_sync0);
            mode["shift_time_sync0"] = dc_time(m.shift_time_sync0);
            mode["cycle_time_sync1"] = dc_time(m.cycle_time_sync1);
            mode["shift_time_sync1"] = dc_time(m.shift_time_sync1);
            modes.push_back(std::move(mode));
        }
    }
    j["op_mode_count"] = modes.size();
    j["op_modes"] = std::move(modes);
    return j;
}

Json eeprom_view(const Device& device) {
    Json j;
    const Eeprom* e = device.eeprom ? &*device.eeprom : nullptr;
    j["present"] = e != nullptr;
    j["byte_size"] = e ? optional_number(e->byte_size) : Json(nullptr);
    // ConfigData: SII words 0..6 (ETG.2010), the ESC configuration the ESC loads at power-up:
    // PDI control, PDI configuration, SYNC impulse length, extended PDI configuration, alias.
    std::optional<std::vector<std::uint8_t>> config;
    if (e && e->config_data) config = e->config_data->bytes();
    Json bytes = Json::array();
    Json words = Json::array();
    if (config) {
        for (const auto b : *config) bytes.push_back(Json{{"hex", hex(b, 2)}});
        for (std::size_t k = 0; k + 1 < config->size(); k += 2)
            words.push_back(Json{{"hex", hex((*config)[k] | ((*config)[k + 1] << 8), 4)}});
    }
    j["config_data_hex"] = e && e->config_data ? e->config_data->text : "";
    j["config_data"] = std::move(bytes);
    j["config_data_words"] = std::move(words);
    j["config_data_byte_count"] = config ? config->size() : 0;
    j["has_config_data"] = config && !config->empty();
    return j;
}

Json fmmus_view(const Device& device) {
    Json list = Json::array();
    for (std::size_t n = 0; n < device.fmmus.size(); ++n) {
        const Fmmu& f = device.fmmus[n];
        list.push_back(Json{{"number", n}, {"type", f.type}, {"sm", optional_number(f.sm)}});
    }
    return list;
}

Json pdo_totals(const Device& device, PdoDirection direction) {
    std::uint64_t entries = 0, bits = 0, default_entries = 0;
    for (const Pdo& p : device.pdos(direction)) {
        entries += p.entries.size();
        bits += p.bit_size();
        if (p.sm) default_entries += p.entries.size();
    }
    return Json{{"pdo_count", device.pdos(direction).size()},
                {"entry_count", entries},
                {"default_entry_count", default_entries},
                {"byte_size", (bits + 7) / 8}};
}

// The default PDO assignment per SM (the PDOs whose Sm attribute names it, in document order) and
// the object that holds it, 0x1C10 + SM (ETG.1000.6).
Json pdo_assignments(const Device& device) {
    std::map<std::uint32_t, std::pair<std::string, Json>> by_sm;
    for (const PdoDirection direction : {PdoDirection::rx, PdoDirection::tx}) {
        for (const Pdo& p : device.pdos(direction)) {
            if (!p.sm) continue;
            auto& slot = by_sm[*p.sm];
            if (slot.first.empty()) {
                slot.first = direction == PdoDirection::rx ? "rx" : "tx";
                slot.second = Json::array();
            }
            slot.second.push_back(Json{{"index", p.index}, {"index_hex", hex(p.index, 4)}});
        }
    }
    Json list = Json::array();
    for (auto& [sm, slot] : by_sm) {
        Json a;
        a["sm"] = sm;
        a["direction"] = slot.first;
        a["object_index"] = 0x1C10 + sm;
        a["object_index_hex"] = hex(0x1C10 + sm, 4);
        a["pdo_count"] = slot.second.size();
        a["pdos"] = std::move(slot.second);
        list.push_back(std::move(a));
    }
    return list;
}

}  // namespace

Json vendor_view(const EtherCATInfo& info) {
    Json j;
    const Vendor* v = info.vendor ? &*info.vendor : nullptr;
    j["id"] = v ? optional_number(v->id) : Json(nullptr);
    j["id_hex"] = hex(v ? v->id.value_or(0) : 0, 8);
    j["name"] = v ? primary_text(v->names) : "";
    j["name_literal"] = c_string_literal(v ? primary_text(v->names) : "");
    return j;
}

Json device_view(const EtherCATInfo& info, const Device& device, const std::string& c_name, const std::string& symbol_prefix,
                 const ViewContext& context) {
    Json d;
    const std::string name = primary_text(device.names);
    d["type"] = device.type.text;
    d["name"] = name;
    d["name_literal"] = c_string_literal(name);
    d["comment"] = c_comment_text(name);
    Json names = Json::array();
    for (const auto& n : device.names) names.push_back(Json{{"lcid", n.lcid ? Json(*n.lcid) : Json(nullptr)}, {"text", n.text}});
    d["names"] = std::move(names);
    d["c_name"] = c_name;
    d["symbol_prefix"] = symbol_prefix;
    d["macro_prefix"] = c_macro_name(symbol_prefix);

    Json identity;
    const std::uint32_t vendor_id = info.vendor ? info.vendor->id.value_or(0) : 0;
    identity["vendor_id"] = vendor_id;
    identity["vendor_id_hex"] = hex(vendor_id, 8);
    identity["product_code"] = device.type.product_code.value_or(0);
    identity["product_code_hex"] = hex(device.type.product_code.value_or(0), 8);
    identity["revision_no"] = device.type.revision_no.value_or(0);
    identity["revision_no_hex"] = hex(device.type.revision_no.value_or(0), 8);
    identity["serial_no"] = device.type.serial_no.value_or(0);
    identity["serial_no_hex"] = hex(device.type.serial_no.value_or(0), 8);
    d["identity"] = std::move(identity);
    d["vendor"] = vendor_view(info);
    d["group_type"] = device.group_type.value_or("");
    d["physics"] = device.physics;
    d["physics_literal"] = c_string_literal(device.physics);
    const Profile* profile = device.profiles.empty() ? nullptr : &device.profiles.front();
    d["profile_no"] = profile && profile->profile_no ? Json(*profile->profile_no) : Json(nullptr);

    Json sms = Json::array();
    for (std::size_t n = 0; n < device.sms.size(); ++n) sms.push_back(sm_view(device.sms[n], n));
    d["sync_manager_count"] = sms.size();
    d["sync_managers"] = std::move(sms);
    d["sm_outputs"] = first_sm_with_role(device, "outputs");
    d["sm_inputs"] = first_sm_with_role(device, "inputs");
    d["fmmus"] = fmmus_view(device);
    d["mailbox"] = mailbox_view(device);
    d["dc"] = dc_view(device);
    d["eeprom"] = eeprom_view(device);

    d["rx_pdos"] = pdos_view(device, PdoDirection::rx);
    d["tx_pdos"] = pdos_view(device, PdoDirection::tx);
    d["pdo_assignments"] = pdo_assignments(device);
    d["pdo_assignment_count"] = d["pdo_assignments"].size();
    d["pdo_totals"] = Json{{"rx", pdo_totals(device, PdoDirection::rx)}, {"tx", pdo_totals(device, PdoDirection::tx)}};
    d["process_image"] = Json{{"rx", process_image_view(device, PdoDirection::rx, context)},
                              {"tx", process_image_view(device, PdoDirection::tx, context)}};

    ObjectsView od = objects_view(device, context);
    d["has_dictionary"] = device.dictionary() != nullptr;
    d["object_count"] = od.objects.size();
    d["entry_count"] = od.entry_count;
    bool soes_storage = false;
    for (const auto& o : od.objects) soes_storage = soes_storage || o["soes"]["stored"].get<bool>();
    d["soes"] = Json{{"has_storage", soes_storage}};
    d["objects"] = std::move(od.objects);
    return d;
}

}  // namespace esi::codegen
