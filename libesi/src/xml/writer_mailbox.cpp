// ESI writer: Mailbox (MailboxType of EtherCATInfo.xsd 1.17) with its protocols (AoE, EoE, CoE,
// FoE, SoE, VoE) and their InitCmds, shared by Device and Module.

#include "esi/model/mailbox_flags.hpp"
#include "xml/writer_model.hpp"

namespace esi::xml_writer {

namespace {

constexpr std::string_view mailbox_order[] = {"AoE", "EoE", "CoE", "FoE", "SoE", "VoE", "VendorSpecific"};
constexpr std::string_view coe_order[] = {"Object", "InitCmd"};
constexpr std::string_view init_cmds_order[] = {"InitCmd"};
constexpr std::string_view soe_order[] = {"InitCmd", "DiagFile", "DiagMessages"};
constexpr std::string_view init_cmd_order[] = {"Transition", "Index", "SubIndex", "IDN", "Type", "Data", "Comment"};

void write_init_cmd(XmlEmitter& out, const InitCmd& cmd) {
    out.begin("InitCmd");
    put_bool(out, "Fixed", cmd.fixed);
    put_bool(out, "CompleteAccess", cmd.complete_access);
    put_bool(out, "OverwrittenByModule", cmd.overwritten_by_module);
    put_decimal(out, "Chn", cmd.channel);
    write_extra_attributes(out, cmd.extras);
    ChildPlacer children(out, cmd.extras, init_cmd_order);
    for (const auto& transition : cmd.transitions) {
        children.at("Transition");
        out.leaf("Transition", transition.text);
    }
    if (cmd.index) {
        children.at("Index");
        write_index(out, *cmd.index, cmd.index_depend_on_slot, cmd.index_depend_on_slot_group);
    }
    if (cmd.subindex) {
        children.at("SubIndex");
        leaf_decimal(out, "SubIndex", *cmd.subindex);
    }
    if (cmd.idn) {
        children.at("IDN");
        leaf_decimal(out, "IDN", *cmd.idn);
    }
    if (cmd.type) {
        children.at("Type");
        leaf_decimal(out, "Type", *cmd.type);
    }
    // has_data tells an empty <Data/> from no Data; data in a hand-built model counts as well.
    if (cmd.has_data || !cmd.data.text.empty()) {
        children.at("Data");
        out.begin("Data");
        put_bool(out, "AdaptAutomatically", cmd.data_adapt_automatically);
        text_hex_data(out, cmd.data);
        out.end();
    }
    if (cmd.comment) {
        children.at("Comment");
        out.leaf("Comment", *cmd.comment);
    }
    children.finish();
    out.end();
}

void write_init_cmds(XmlEmitter& out, ChildPlacer& children, const std::vector<InitCmd>& cmds) {
    for (const auto& cmd : cmds) {
        children.at("InitCmd");
        write_init_cmd(out, cmd);
    }
}

void write_plain_protocol(XmlEmitter& out, std::string_view element, const PlainProtocol& protocol) {
    out.begin(element);
    write_extra_attributes(out, protocol.extras);
    ChildPlacer children(out, protocol.extras, no_children);
    children.finish();
    out.end();
}

// A protocol element with InitCmds: `attributes` writes its typed attributes, then come the
// unknown attributes, the InitCmds and the unknown children placed by `order`.
template <class Protocol, class Attributes>
void write_protocol(XmlEmitter& out, std::string_view element, const Protocol& protocol, ChildOrder order,
                    Attributes&& attributes) {
    out.begin(element);
    attributes();
    write_extra_attributes(out, protocol.extras);
    ChildPlacer children(out, protocol.extras, order);
    write_init_cmds(out, children, protocol.init_cmds);
    children.finish();
    out.end();
}

template <class Protocol, class Flags>
void put_flags(XmlEmitter& out, const Protocol& protocol, const Flags& flags) {
    for (const auto& flag : flags) put_bool(out, flag.attribute, protocol.*flag.field);
}

}  // namespace

void write_mailbox(XmlEmitter& out, const Mailbox& mailbox) {
    out.begin("Mailbox");
    put_bool(out, "DataLinkLayer", mailbox.data_link_layer);
    put_bool(out, "RealTimeMode", mailbox.real_time_mode);
    write_extra_attributes(out, mailbox.extras);
    ChildPlacer children(out, mailbox.extras, mailbox_order);
    if (const auto& aoe = mailbox.aoe) {
        children.at("AoE");
        write_protocol(out, "AoE", *aoe, init_cmds_order, [&] { put_flags(out, *aoe, aoe_flags); });
    }
    if (const auto& eoe = mailbox.eoe) {
        children.at("EoE");
        write_protocol(out, "EoE", *eoe, init_cmds_order, [&] { put_flags(out, *eoe, eoe_flags); });
    }
    if (const auto& coe = mailbox.coe) {
        children.at("CoE");
        write_protocol(out, "CoE", *coe, coe_order, [&] {
            const std::span<const MailboxFlag<CoeProtocol>> flags = coe_flags;
            put_flags(out, *coe, flags.first(coe_flags_before_eds_file));
            put_text(out, "EdsFile", coe->eds_file);
            put_decimal(out, "DS402Channels", coe->ds402_channels);
            put_flags(out, *coe, flags.subspan(coe_flags_before_eds_file));
        });
    }
    if (mailbox.foe) {
        children.at("FoE");
        write_plain_protocol(out, "FoE", *mailbox.foe);
    }
    if (const auto& soe = mailbox.soe) {
        children.at("SoE");
        write_protocol(out, "SoE", *soe, soe_order, [&] {
            put_decimal(out, "ChannelCount", soe->channel_count);
            put_flags(out, *soe, soe_flags);
        });
    }
    if (mailbox.voe) {
        children.at("VoE");
        write_plain_protocol(out, "VoE", *mailbox.voe);
    }
    children.finish();
    out.end();
}

}  // namespace esi::xml_writer
