// `mailbox:` (the protocols and, when SyncManagers are derived, the mailbox sizes and addresses)
// and the InitCmds of CoE, SoE, EoE and AoE.

#include "import/import_writer.hpp"

namespace esi::import_detail {

namespace {

YNode transitions(const std::vector<Transition>& ts) {
    if (ts.size() == 1) return YNode::text(ts.front().text);
    YNode s = YNode::seq();
    for (const auto& t : ts) s.push(YNode::text(t.text));
    return s;
}

}  // namespace

YNode ImportWriter::init_cmd(const InitCmd& c, MailboxProtocol protocol, const std::string& path) {
    YNode m = YNode::map();
    if (c.transitions.empty()) warn(path, "an InitCmd without Transition cannot be written");
    m.set("transition", transitions(c.transitions));
    if (protocol == MailboxProtocol::coe) {
        if (!c.index) warn(path, "a CoE InitCmd without Index cannot be written");
        m.set("object", YNode::hex(c.index.value_or(0), 4));
        if (c.subindex) m.set("subindex", YNode::unsigned_integer(*c.subindex));
    }
    if (protocol == MailboxProtocol::soe) {
        if (c.idn) m.set("idn", YNode::integer(*c.idn));
        if (c.channel) m.set("channel", YNode::integer(*c.channel));
    }
    if (protocol == MailboxProtocol::eoe) m.set("type", YNode::integer(c.type.value_or(0)));
    if (c.has_data) {
        if (valid_hex(c.data)) m.set("data", hex_data(c.data));
        else warn(path + "/Data", "'" + c.data.text + "' is not hex bytes; dropped");
    } else {
        warn(path, "an InitCmd without Data cannot be written; written as empty data");
        m.set("data", YNode::text(""));
    }
    if (c.comment) m.set("comment", YNode::text(*c.comment));
    if (protocol == MailboxProtocol::coe && c.complete_access) m.set("complete_access", YNode::boolean(*c.complete_access));
    if (protocol == MailboxProtocol::coe || protocol == MailboxProtocol::soe) {
        if (c.fixed) m.set("fixed", YNode::boolean(*c.fixed));
        if (c.overwritten_by_module) m.set("overwritten_by_module", YNode::boolean(*c.overwritten_by_module));
        if (c.data_adapt_automatically) m.set("adapt_automatically", YNode::boolean(*c.data_adapt_automatically));
    }
    if (protocol == MailboxProtocol::coe) {
        if (c.index_depend_on_slot) m.set("index_depend_on_slot", YNode::boolean(*c.index_depend_on_slot));
        if (c.index_depend_on_slot_group) m.set("index_depend_on_slot_group", YNode::boolean(*c.index_depend_on_slot_group));
    }
    set_extras(m, "xml", c.extras);
    return m;
}

YNode ImportWriter::mailbox(const Mailbox& mb, const Device* device, const OmitPlan& plan, const std::string& path) {
    YNode m = YNode::map();
    if (device && plan.sms) {
        // The mailbox SMs are derived from these (docs/yaml-format.md, SyncManagers).
        const SyncManager* out = nullptr;
        const SyncManager* in = nullptr;
        for (const auto& sm : device->sms) {
            if (!out && sm.type == "MBoxOut") out = &sm;
            if (!in && sm.type == "MBoxIn") in = &sm;
        }
        if (out && in && out->default_size && in->default_size && *out->default_size == *in->default_size) {
            m.set("size", YNode::unsigned_integer(*out->default_size));
        } else {
            if (out && out->default_size) m.set("out_size", YNode::unsigned_integer(*out->default_size));
            if (in && in->default_size) m.set("in_size", YNode::unsigned_integer(*in->default_size));
        }
        if (out && out->start_address && *out->start_address != 0x1000) m.set("out_address", YNode::hex(*out->start_address, 4));
        // in_address follows MBoxOut unless given (docs/yaml-format.md).
        const std::uint32_t follows = out ? out->start_address.value_or(0x1000) + out->default_size.value_or(0) : 0;
        if (in && in->start_address && (!out || *in->start_address != follows)) m.set("in_address", YNode::hex(*in->start_address, 4));
    }
    if (mb.data_link_layer && !(plan.data_link_layer && *mb.data_link_layer))
        m.set("data_link_layer", YNode::boolean(*mb.data_link_layer));
    if (mb.real_time_mode) m.set("real_time_mode", YNode::boolean(*mb.real_time_mode));
    if (mb.aoe) {
        YNode p = YNode::map();
        if (mb.aoe->ads_router) p.set("ads_router", YNode::boolean(*mb.aoe->ads_router));
        if (mb.aoe->generate_own_net_id) p.set("generate_own_net_id", YNode::boolean(*mb.aoe->generate_own_net_id));
        if (mb.aoe->initialize_own_net_id) p.set("initialize_own_net_id", YNode::boolean(*mb.aoe->initialize_own_net_id));
        if (!mb.aoe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < mb.aoe->init_cmds.size(); ++i)
                list.push(init_cmd(mb.aoe->init_cmds[i], MailboxProtocol::aoe, path + "/AoE/InitCmd[" + std::to_string(i + 1) + "]"));
            p.set("init", std::move(list));
        }
        set_extras(p, "xml", mb.aoe->extras);
        m.set("aoe", std::move(p));
    }
    if (mb.eoe) {
        YNode p = YNode::map();
        if (mb.eoe->ip) p.set("ip", YNode::boolean(*mb.eoe->ip));
        if (mb.eoe->mac) p.set("mac", YNode::boolean(*mb.eoe->mac));
        if (mb.eoe->time_stamp) p.set("time_stamp", YNode::boolean(*mb.eoe->time_stamp));
        if (!mb.eoe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < mb.eoe->init_cmds.size(); ++i)
                list.push(init_cmd(mb.eoe->init_cmds[i], MailboxProtocol::eoe, path + "/EoE/InitCmd[" + std::to_string(i + 1) + "]"));
            p.set("init", std::move(list));
        }
        set_extras(p, "xml", mb.eoe->extras);
        m.set("eoe", std::move(p));
    }
    if (mb.coe) {
        const CoeProtocol& c = *mb.coe;
        YNode p = YNode::map();
        auto flag = [&](const char* key, const std::optional<bool>& v) {
            if (v) p.set(key, YNode::boolean(*v));
        };
        flag("sdo_info", c.sdo_info);
        flag("pdo_assign", c.pdo_assign);
        flag("pdo_config", c.pdo_config);
        flag("pdo_upload", c.pdo_upload);
        flag("complete_access", c.complete_access);
        flag("segmented_sdo", c.segmented_sdo);
        flag("diag_history", c.diag_history);
        flag("sdo_upload_with_max_length", c.sdo_upload_with_max_length);
        flag("time_distribution", c.time_distribution);
        flag("module_od", c.module_od);
        if (c.eds_file) p.set("eds_file", YNode::text(*c.eds_file));
        if (c.ds402_channels) p.set("ds402_channels", YNode::integer(*c.ds402_channels));
        set_extras(p, "xml", c.extras);
        m.set("coe", std::move(p));
    }
    if (mb.foe) {
        YNode p = YNode::map();
        set_extras(p, "xml", mb.foe->extras);
        m.set("foe", std::move(p));
    }
    if (mb.soe) {
        YNode p = YNode::map();
        if (mb.soe->channel_count) p.set("channel_count", YNode::integer(*mb.soe->channel_count));
        if (mb.soe->drive_follows_bit3_support) p.set("drive_follows_bit3_support", YNode::boolean(*mb.soe->drive_follows_bit3_support));
        if (!mb.soe->init_cmds.empty()) {
            YNode list = YNode::seq();
            for (std::size_t i = 0; i < mb.soe->init_cmds.size(); ++i)
                list.push(init_cmd(mb.soe->init_cmds[i], MailboxProtocol::soe, path + "/SoE/InitCmd[" + std::to_string(i + 1) + "]"));
            p.set("init", std::move(list));
        }
        set_extras(p, "xml", mb.soe->extras);
        m.set("soe", std::move(p));
    }
    if (mb.voe) {
        YNode p = YNode::map();
        set_extras(p, "xml", mb.voe->extras);
        m.set("voe", std::move(p));
    }
    set_extras(m, "xml", mb.extras);
    return m;
}

}  // namespace esi::import_detail
