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

ViewValue optional_number(const std::optional<std::uint32_t>& value) { return value ? ViewValue::of_uint(*value) : ViewValue::null(); }

std::string lower(std::string_view text) {
    std::string out(trim(text));
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

// The SM's job from its text (ETG.2000 SmType: MBoxOut, MBoxIn, Outputs, Inputs).
std::string_view sm_role(const SyncManager& sm) {
    const std::string t = lower(sm.type);
    if (t == "mboxout") return "mailbox_out";
    if (t == "mboxin") return "mailbox_in";
    if (t == "outputs") return "outputs";
    if (t == "inputs") return "inputs";
    return "other";
}

// SII SyncM category type byte (ETG.2010): 0 unused, 1 mailbox out, 2 mailbox in, 3 outputs, 4 inputs.
int role_code(std::string_view role) {
    if (role == "mailbox_out") return 1;
    if (role == "mailbox_in") return 2;
    if (role == "outputs") return 3;
    if (role == "inputs") return 4;
    return 0;
}

ViewValue sm_view(const SyncManager& sm, std::size_t number, ViewArena& arena) {
    ObjectBuilder j(arena);
    const std::string_view role = sm_role(sm);
    j.add("present", true);
    j.add("number", number);
    j.add("type", sm.type);
    j.add("role", ViewValue::of_static(role));
    j.add("role_code", role_code(role));
    j.add("start_address", optional_number(sm.start_address));
    j.add("start_address_hex", hex_text(sm.start_address.value_or(0), 4));
    j.add("default_size", optional_number(sm.default_size));
    j.add("min_size", optional_number(sm.min_size));
    j.add("max_size", optional_number(sm.max_size));
    // ESC register 0x0804+8n: ControlByte; bit 6 enables the watchdog trigger.
    j.add("control_byte", optional_number(sm.control_byte));
    j.add("control_byte_hex", hex_text(sm.control_byte.value_or(0), 2));
    j.add("watchdog_trigger", (sm.control_byte.value_or(0) & 0x40u) != 0);
    j.add("enable", optional_number(sm.enable));
    j.add("enabled", sm.enable.value_or(0) != 0);
    j.add("virtual", sm.is_virtual.value_or(false));
    return j.finish();
}

ViewValue absent_sm(ViewArena& arena) {
    ObjectBuilder j(arena);
    j.add("present", false);
    j.add("number", nullptr);
    j.add("type", ViewValue::of_static(""));
    j.add("role", ViewValue::of_static(""));
    j.add("role_code", 0);
    j.add("start_address", nullptr);
    j.add("start_address_hex", ViewValue::of_static("0x0000"));
    j.add("default_size", nullptr);
    j.add("min_size", nullptr);
    j.add("max_size", nullptr);
    j.add("control_byte", nullptr);
    j.add("control_byte_hex", ViewValue::of_static("0x00"));
    j.add("watchdog_trigger", false);
    j.add("enable", nullptr);
    j.add("enabled", false);
    j.add("virtual", false);
    return j.finish();
}

ViewValue first_sm_with_role(const Device& device, std::string_view role, ViewArena& arena) {
    for (std::size_t n = 0; n < device.sms.size(); ++n)
        if (sm_role(device.sms[n]) == role) return sm_view(device.sms[n], n, arena);
    return absent_sm(arena);
}

ViewValue hex_byte_list(const std::vector<std::uint8_t>& bytes, ViewArena& arena) {
    ListBuilder list(arena);
    for (const auto b : bytes) {
        ObjectBuilder item(arena);
        item.add("hex", hex_text(b, 2));
        list.add(item.finish());
    }
    return list.finish();
}

ViewValue init_cmd_view(const InitCmd& cmd, std::string_view protocol, ViewArena& arena) {
    ObjectBuilder j(arena);
    j.add("protocol", ViewValue::of_static(protocol));
    ListBuilder transitions(arena);
    std::string text;
    for (const auto& t : cmd.transitions) {
        ObjectBuilder transition(arena);
        transition.add("name", t.text);
        transitions.add(transition.finish());
        text += (text.empty() ? "" : " ") + t.text;
    }
    j.add("transitions", transitions.finish());
    j.add("transitions_text", text);
    j.add("has_index", cmd.index.has_value());
    j.add("index", optional_number(cmd.index));
    j.add("index_hex", hex_text(cmd.index.value_or(0), 4));
    j.add("subindex", optional_number(cmd.subindex));
    j.add("subindex_hex", hex_text(cmd.subindex.value_or(0), 2));
    const auto bytes = cmd.data.bytes();
    j.add("data_hex", cmd.data.text);
    j.add("data", hex_byte_list(bytes ? *bytes : std::vector<std::uint8_t>{}, arena));
    j.add("data_literal", c_string_literal(bytes ? std::string(bytes->begin(), bytes->end()) : std::string()));
    j.add("byte_count", bytes ? bytes->size() : 0);
    j.add("complete_access", cmd.complete_access.value_or(false));
    j.add("comment", c_comment_text(cmd.comment.value_or("")));
    return j.finish();
}

ViewValue mailbox_view(const Device& device, ViewArena& arena) {
    ObjectBuilder j(arena);
    const Mailbox* mb = device.mailbox ? &*device.mailbox : nullptr;
    j.add("present", mb != nullptr);
    j.add("out", first_sm_with_role(device, "mailbox_out", arena));
    j.add("in", first_sm_with_role(device, "mailbox_in", arena));
    {
        ObjectBuilder protocols(arena);
        protocols.add("aoe", mb && mb->aoe.has_value());
        protocols.add("eoe", mb && mb->eoe.has_value());
        protocols.add("coe", mb && mb->coe.has_value());
        protocols.add("foe", mb && mb->foe.has_value());
        protocols.add("soe", mb && mb->soe.has_value());
        protocols.add("voe", mb && mb->voe.has_value());
        j.add("protocols", protocols.finish());
    }
    const std::uint16_t bits = mb ? mb->protocol_bits() : 0;
    j.add("protocol_bits", bits);
    j.add("protocol_bits_hex", hex_text(bits, 4));
    j.add("data_link_layer", mb && mb->data_link_layer.value_or(false));

    {
        ObjectBuilder coe(arena);
        const CoeProtocol* c = mb && mb->coe ? &*mb->coe : nullptr;
        coe.add("sdo_info", c && c->sdo_info.value_or(false));
        coe.add("pdo_assign", c && c->pdo_assign.value_or(false));
        coe.add("pdo_config", c && c->pdo_config.value_or(false));
        coe.add("pdo_upload", c && c->pdo_upload.value_or(false));
        coe.add("complete_access", c && c->complete_access.value_or(false));
        coe.add("segmented_sdo", c && c->segmented_sdo.value_or(false));
        j.add("coe", coe.finish());
    }

    ListBuilder init_cmds(arena);
    if (mb)
        mb->for_each_init_cmd(
            [&](MailboxProtocol protocol, const InitCmd& cmd) { init_cmds.add(init_cmd_view(cmd, to_string(protocol), arena)); });
    j.add("init_cmds", init_cmds.finish());

    // Eeprom/BootStrap: bootstrap mailbox out offset, out size, in offset, in size (little-endian
    // words), the values SII words 0x14..0x17 carry (ETG.2010).
    std::optional<std::vector<std::uint8_t>> raw;
    if (device.eeprom && device.eeprom->boot_strap) raw = device.eeprom->boot_strap->bytes();
    const bool has_boot = raw && raw->size() >= 8;
    auto word = [&](std::size_t k) -> std::uint32_t { return has_boot ? (*raw)[2 * k] | ((*raw)[2 * k + 1] << 8) : 0; };
    ObjectBuilder boot(arena);
    boot.add("present", has_boot);
    boot.add("out_start_address", word(0));
    boot.add("out_start_address_hex", hex_text(word(0), 4));
    boot.add("out_size", word(1));
    boot.add("in_start_address", word(2));
    boot.add("in_start_address_hex", hex_text(word(2), 4));
    boot.add("in_size", word(3));
    j.add("bootstrap", boot.finish());
    return j.finish();
}

ViewValue dc_time(const std::optional<DcTime>& t, ViewArena& arena) {
    ObjectBuilder j(arena);
    j.add("present", t.has_value());
    j.add("value", t ? t->value : std::int64_t{0});
    j.add("factor", t && t->factor ? ViewValue::of_int(*t->factor) : ViewValue::null());
    return j.finish();
}

ViewValue dc_view(const Device& device, ViewArena& arena) {
    ObjectBuilder j(arena);
    j.add("present", device.dc.has_value() && !device.dc->op_modes.empty());
    ListBuilder modes(arena);
    if (device.dc) {
        IdentifierScope scope;
        for (const auto& m : device.dc->op_modes) {
            ObjectBuilder mode(arena);
            mode.add("name", m.name);
            mode.add("c_name", scope.claim(c_identifier(m.name, "op_mode")));
            mode.add("name_literal", c_string_literal(m.name));
            mode.add("description", m.desc.value_or(""));
            mode.add("description_literal", c_string_literal(m.desc.value_or("")));
            mode.add("assign_activate", m.assign_activate);
            mode.add("assign_activate_hex", hex_text(m.assign_activate, 4));
            mode.add("cycle_time_sync0", dc_time(m.cycle_time_sync0, arena));
            mode.add("shift_time_sync0", dc_time(m.shift_time_sync0, arena));
            mode.add("cycle_time_sync1", dc_time(m.cycle_time_sync1, arena));
            mode.add("shift_time_sync1", dc_time(m.shift_time_sync1, arena));
            modes.add(mode.finish());
        }
    }
    j.add("op_mode_count", modes.size());
    j.add("op_modes", modes.finish());
    return j.finish();
}

ViewValue eeprom_view(const Device& device, ViewArena& arena) {
    ObjectBuilder j(arena);
    const Eeprom* e = device.eeprom ? &*device.eeprom : nullptr;
    j.add("present", e != nullptr);
    j.add("byte_size", e ? optional_number(e->byte_size) : ViewValue::null());
    // ConfigData: SII words 0..6 (ETG.2010), the ESC configuration the ESC loads at power-up:
    // PDI control, PDI configuration, SYNC impulse length, extended PDI configuration, alias.
    std::optional<std::vector<std::uint8_t>> config;
    if (e && e->config_data) config = e->config_data->bytes();
    ListBuilder words(arena);
    if (config) {
        for (std::size_t k = 0; k + 1 < config->size(); k += 2) {
            ObjectBuilder word(arena);
            word.add("hex", hex_text((*config)[k] | ((*config)[k + 1] << 8), 4));
            words.add(word.finish());
        }
    }
    j.add("config_data_hex", e && e->config_data ? e->config_data->text : std::string());
    j.add("config_data", hex_byte_list(config ? *config : std::vector<std::uint8_t>{}, arena));
    j.add("config_data_words", words.finish());
    j.add("config_data_byte_count", config ? config->size() : 0);
    j.add("has_config_data", config && !config->empty());
    return j.finish();
}

ViewValue fmmus_view(const Device& device, ViewArena& arena) {
    ListBuilder list(arena);
    for (std::size_t n = 0; n < device.fmmus.size(); ++n) {
        const Fmmu& f = device.fmmus[n];
        ObjectBuilder fmmu(arena);
        fmmu.add("number", n);
        fmmu.add("type", f.type);
        fmmu.add("sm", optional_number(f.sm));
        list.add(fmmu.finish());
    }
    return list.finish();
}

ViewValue pdo_totals(const Device& device, PdoDirection direction, ViewArena& arena) {
    std::uint64_t entries = 0, bits = 0, default_entries = 0;
    for (const Pdo& p : device.pdos(direction)) {
        entries += p.entries.size();
        bits += p.bit_size();
        if (p.sm) default_entries += p.entries.size();
    }
    ObjectBuilder j(arena);
    j.add("pdo_count", device.pdos(direction).size());
    j.add("entry_count", entries);
    j.add("default_entry_count", default_entries);
    j.add("byte_size", (bits + 7) / 8);
    return j.finish();
}

// The default PDO assignment per SM (the PDOs whose Sm attribute names it, in document order) and
// the object that holds it, 0x1C10 + SM (ETG.1000.6).
ViewValue pdo_assignments(const Device& device, ViewArena& arena) {
    std::map<std::uint32_t, std::pair<std::string_view, std::vector<const Pdo*>>> by_sm;
    for (const PdoDirection direction : {PdoDirection::rx, PdoDirection::tx}) {
        for (const Pdo& p : device.pdos(direction)) {
            if (!p.sm) continue;
            auto& slot = by_sm[*p.sm];
            if (slot.first.empty()) slot.first = direction == PdoDirection::rx ? "rx" : "tx";
            slot.second.push_back(&p);
        }
    }
    ListBuilder list(arena);
    for (const auto& [sm, slot] : by_sm) {
        ObjectBuilder a(arena);
        a.add("sm", sm);
        a.add("direction", ViewValue::of_static(slot.first));
        a.add("object_index", 0x1C10 + sm);
        a.add("object_index_hex", hex_text(0x1C10 + sm, 4));
        a.add("pdo_count", slot.second.size());
        ListBuilder pdos(arena);
        for (const Pdo* p : slot.second) {
            ObjectBuilder pdo(arena);
            pdo.add("index", p->index);
            pdo.add("index_hex", hex_text(p->index, 4));
            pdos.add(pdo.finish());
        }
        a.add("pdos", pdos.finish());
        list.add(a.finish());
    }
    return list.finish();
}

}  // namespace

ViewValue vendor_view(const EtherCATInfo& info, ViewArena& arena) {
    ObjectBuilder j(arena);
    const Vendor* v = info.vendor ? &*info.vendor : nullptr;
    j.add("id", v ? optional_number(v->id) : ViewValue::null());
    j.add("id_hex", hex_text(v ? v->id.value_or(0) : 0, 8));
    j.add("name", v ? primary_text(v->names) : std::string());
    j.add("name_literal", c_string_literal(v ? primary_text(v->names) : ""));
    return j.finish();
}

ViewValue device_view(const EtherCATInfo& info, const Device& device, const std::string& c_name, const std::string& symbol_prefix,
                      const ViewContext& context) {
    ViewArena& arena = *context.arena;
    ObjectBuilder d(arena);
    const std::string name = primary_text(device.names);
    d.add("type", device.type.text);
    d.add("name", name);
    d.add("name_literal", c_string_literal(name));
    d.add("comment", c_comment_text(name));
    {
        ListBuilder names(arena);
        for (const auto& n : device.names) {
            ObjectBuilder entry(arena);
            entry.add("lcid", n.lcid);
            entry.add("text", n.text);
            names.add(entry.finish());
        }
        d.add("names", names.finish());
    }
    d.add("c_name", c_name);
    d.add("symbol_prefix", symbol_prefix);
    d.add("macro_prefix", c_macro_name(symbol_prefix));

    {
        ObjectBuilder identity(arena);
        const std::uint32_t vendor_id = info.vendor ? info.vendor->id.value_or(0) : 0;
        identity.add("vendor_id", vendor_id);
        identity.add("vendor_id_hex", hex_text(vendor_id, 8));
        identity.add("product_code", device.type.product_code.value_or(0));
        identity.add("product_code_hex", hex_text(device.type.product_code.value_or(0), 8));
        identity.add("revision_no", device.type.revision_no.value_or(0));
        identity.add("revision_no_hex", hex_text(device.type.revision_no.value_or(0), 8));
        identity.add("serial_no", device.type.serial_no.value_or(0));
        identity.add("serial_no_hex", hex_text(device.type.serial_no.value_or(0), 8));
        d.add("identity", identity.finish());
    }
    d.add("vendor", vendor_view(info, arena));
    d.add("group_type", device.group_type.value_or(""));
    d.add("physics", device.physics);
    d.add("physics_literal", c_string_literal(device.physics));
    const Profile* profile = device.profiles.empty() ? nullptr : &device.profiles.front();
    d.add("profile_no", profile && profile->profile_no ? ViewValue::of_int(*profile->profile_no) : ViewValue::null());

    {
        ListBuilder sms(arena);
        for (std::size_t n = 0; n < device.sms.size(); ++n) sms.add(sm_view(device.sms[n], n, arena));
        d.add("sync_manager_count", sms.size());
        d.add("sync_managers", sms.finish());
    }
    d.add("sm_outputs", first_sm_with_role(device, "outputs", arena));
    d.add("sm_inputs", first_sm_with_role(device, "inputs", arena));
    d.add("fmmus", fmmus_view(device, arena));
    d.add("mailbox", mailbox_view(device, arena));
    d.add("dc", dc_view(device, arena));
    d.add("eeprom", eeprom_view(device, arena));

    d.add("rx_pdos", pdos_view(device, PdoDirection::rx, context));
    d.add("tx_pdos", pdos_view(device, PdoDirection::tx, context));
    const ViewValue assignments = pdo_assignments(device, arena);
    d.add("pdo_assignments", assignments);
    d.add("pdo_assignment_count", std::size_t{assignments.size});
    {
        ObjectBuilder totals(arena);
        totals.add("rx", pdo_totals(device, PdoDirection::rx, arena));
        totals.add("tx", pdo_totals(device, PdoDirection::tx, arena));
        d.add("pdo_totals", totals.finish());
    }
    {
        ObjectBuilder image(arena);
        image.add("rx", process_image_view(device, PdoDirection::rx, context));
        image.add("tx", process_image_view(device, PdoDirection::tx, context));
        d.add("process_image", image.finish());
    }

    const ObjectsView od = objects_view(device, context);
    d.add("has_dictionary", device.dictionary() != nullptr);
    d.add("object_count", std::size_t{od.objects.size});
    d.add("entry_count", od.entry_count);
    d.add("soes", soes_view(device, od.soes_storage, arena));
    d.add("objects", od.objects);
    return d.finish();
}

}  // namespace esi::codegen
