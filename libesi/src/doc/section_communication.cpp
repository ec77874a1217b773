// The communication sections of a page: mailbox (protocols, sizes, CoE details, bootstrap),
// SyncManagers and FMMUs.

#include <string>

#include "doc/markup.hpp"
#include "doc/sections.hpp"
#include "esi/plural.hpp"

namespace esi::doc {

namespace {

std::string joined(const std::vector<std::string>& parts) {
    std::string out;
    for (const auto& p : parts) out += (out.empty() ? "" : ", ") + p;
    return out;
}

void add_if(std::vector<std::string>& out, const std::optional<bool>& flag, const char* word) {
    if (flag.value_or(false)) out.emplace_back(word);
}

const SyncManager* first_sm(const Device& device, std::string_view type) {
    for (const auto& sm : device.sms)
        if (sm.type == type) return &sm;
    return nullptr;
}

ViewValue mailbox_sm(const SyncManager* sm, ViewArena& arena) {
    if (!sm) return ViewValue::null();
    PageObject o(arena);
    o.add("start_hex", sm->start_address ? hex(*sm->start_address, 4) : std::string());
    o.add("size", sm->default_size);
    o.add("size_text", sm->default_size ? counted(*sm->default_size, "byte") : std::string());
    return o.finish();
}

// Eeprom/BootStrap: out offset, out size, in offset, in size as little-endian words (SII words
// 0x14-0x17, ETG.2010).
ViewValue bootstrap_view(const Device& device, ViewArena& arena) {
    if (!device.eeprom || !device.eeprom->boot_strap) return ViewValue::null();
    const auto bytes = device.eeprom->boot_strap->bytes();
    if (!bytes || bytes->size() < 8) return ViewValue::null();
    const auto word = [&](std::size_t k) { return static_cast<std::uint32_t>((*bytes)[2 * k] | (*bytes)[2 * k + 1] << 8); };
    PageObject o(arena);
    o.add("out_start_hex", hex(word(0), 4));
    o.add("out_size", word(1));
    o.add("out_size_text", counted(word(1), "byte"));
    o.add("in_start_hex", hex(word(2), 4));
    o.add("in_size", word(3));
    o.add("in_size_text", counted(word(3), "byte"));
    return o.finish();
}

}  // namespace

ViewValue mailbox_section(const Device& device, const PageContext& context) {
    if (!device.mailbox) return ViewValue::null();
    const Mailbox& m = *device.mailbox;
    ViewArena& arena = *context.arena;
    std::vector<std::string> protocols;
    if (m.coe) protocols.emplace_back("CoE");
    if (m.soe) protocols.emplace_back("SoE");
    if (m.eoe) protocols.emplace_back("EoE");
    if (m.foe) protocols.emplace_back("FoE");
    if (m.aoe) protocols.emplace_back("AoE");
    if (m.voe) protocols.emplace_back("VoE");
    std::vector<std::string> details;
    if (m.coe) {
        add_if(details, m.coe->sdo_info, "CoE SDO information");
        add_if(details, m.coe->pdo_assign, "CoE PDO assignment");
        add_if(details, m.coe->pdo_config, "CoE PDO configuration");
        add_if(details, m.coe->pdo_upload, "CoE PDO upload");
        add_if(details, m.coe->complete_access, "CoE complete access");
        add_if(details, m.coe->segmented_sdo, "CoE segmented SDO");
        add_if(details, m.coe->diag_history, "CoE diagnosis history");
    }
    if (m.eoe) {
        add_if(details, m.eoe->ip, "EoE IP");
        add_if(details, m.eoe->mac, "EoE MAC");
    }
    if (m.soe && m.soe->channel_count) details.push_back("SoE " + std::to_string(*m.soe->channel_count) + " channel(s)");
    add_if(details, m.data_link_layer, "data link layer");
    PageObject o(arena);
    o.add("protocols", protocols.empty() ? std::string("none") : joined(protocols));
    o.add("details", joined(details));
    o.add("out", mailbox_sm(first_sm(device, "MBoxOut"), arena));
    o.add("in", mailbox_sm(first_sm(device, "MBoxIn"), arena));
    o.add("bootstrap", bootstrap_view(device, arena));
    return o.finish();
}

ViewValue sync_managers_list(const Device& device, const PageContext& context) {
    ViewArena& arena = *context.arena;
    ListBuilder list(arena);
    for (std::size_t i = 0; i < device.sms.size(); ++i) {
        const SyncManager& sm = device.sms[i];
        std::vector<std::string> flags;
        add_if(flags, sm.is_virtual, "virtual");
        add_if(flags, sm.fixed_assignment, "fixed assignment");
        add_if(flags, sm.op_only, "Op only");
        add_if(flags, sm.watchdog, "watchdog");
        PageObject o(arena);
        o.add("number", i);
        o.add("type", sm.type);
        o.add("start_hex", sm.start_address ? hex(*sm.start_address, 4) : std::string());
        o.add("default_size", sm.default_size);
        o.add("min_size", sm.min_size);
        o.add("max_size", sm.max_size);
        o.add("control_byte_hex", sm.control_byte ? hex(*sm.control_byte, 2) : std::string());
        o.add("enable", sm.enable);
        o.add("flags", joined(flags));
        list.add(o.finish());
    }
    return list.finish();
}

ViewValue fmmus_list(const Device& device, const PageContext& context) {
    ViewArena& arena = *context.arena;
    ListBuilder list(arena);
    for (std::size_t i = 0; i < device.fmmus.size(); ++i) {
        const Fmmu& f = device.fmmus[i];
        PageObject o(arena);
        o.add("number", i);
        o.add("type", f.type);
        o.add("sm", f.sm);
        o.add("su", f.su);
        list.add(o.finish());
    }
    return list.finish();
}

}  // namespace esi::doc
