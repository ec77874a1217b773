// ESI XML -> model: Mailbox (of a Device or a Module) with its protocols (CoE, EoE, SoE, AoE,
// FoE, VoE) and the InitCmds a master sends on state transitions.

#include "xml/reader_context.hpp"

namespace esi::xml_reader {

void Reader::read_init_cmd(InitCmd& cmd, const pugi::xml_node n) {
    cmd.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "Fixed")) cmd.fixed = boolean(a, n);
        else if (is(an, "CompleteAccess")) cmd.complete_access = boolean(a, n);
        else if (is(an, "OverwrittenByModule")) cmd.overwritten_by_module = boolean(a, n);
        else if (is(an, "Chn")) cmd.channel = i32(a, n);
        else keep(cmd.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Transition")) cmd.transitions.push_back(Transition{text_of(c), pos_of(c)});
        else if (is(name, "Index")) {
            cmd.index = u32(c);
            depend_on_slot(c, cmd.index_depend_on_slot, cmd.index_depend_on_slot_group);
        } else if (is(name, "SubIndex")) cmd.subindex = u32(c);
        else if (is(name, "IDN")) cmd.idn = i64(c);
        else if (is(name, "Type")) cmd.type = i64(c);
        else if (is(name, "Data")) {
            cmd.data = hex(c);
            cmd.has_data = true;
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute())
                if (is(a.name(), "AdaptAutomatically")) cmd.data_adapt_automatically = boolean(a, c);
        } else if (is(name, "Comment")) cmd.comment = text_of(c);
        else keep(cmd.extras, c, previous);
    });
}

void Reader::read_coe(CoeProtocol& coe, const pugi::xml_node n) {
    coe.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "SdoInfo")) coe.sdo_info = boolean(a, n);
        else if (is(an, "PdoAssign")) coe.pdo_assign = boolean(a, n);
        else if (is(an, "PdoConfig")) coe.pdo_config = boolean(a, n);
        else if (is(an, "PdoUpload")) coe.pdo_upload = boolean(a, n);
        else if (is(an, "CompleteAccess")) coe.complete_access = boolean(a, n);
        else if (is(an, "SegmentedSdo")) coe.segmented_sdo = boolean(a, n);
        else if (is(an, "DiagHistory")) coe.diag_history = boolean(a, n);
        else if (is(an, "SdoUploadWithMaxLength")) coe.sdo_upload_with_max_length = boolean(a, n);
        else if (is(an, "TimeDistribution")) coe.time_distribution = boolean(a, n);
        else if (is(an, "ModuleOD")) coe.module_od = boolean(a, n);
        else if (is(an, "EdsFile")) coe.eds_file = a.value();
        else if (is(an, "DS402Channels")) coe.ds402_channels = i32(a, n);
        else keep(coe.extras, a);
    }
    reserve_for(coe.init_cmds, n, "InitCmd");
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "InitCmd")) read_init_cmd(coe.init_cmds.emplace_back(), c);
        else keep(coe.extras, c, previous);
    });
}

void Reader::read_mailbox(Mailbox& m, const pugi::xml_node n) {
    m.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "DataLinkLayer")) m.data_link_layer = boolean(a, n);
        else if (is(an, "RealTimeMode")) m.real_time_mode = boolean(a, n);
        else keep(m.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "CoE")) {
            read_coe(m.coe.emplace(), c);
        } else if (is(name, "EoE")) {
            EoeProtocol eoe;
            eoe.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "IP")) eoe.ip = boolean(a, c);
                else if (is(an, "MAC")) eoe.mac = boolean(a, c);
                else if (is(an, "TimeStamp")) eoe.time_stamp = boolean(a, c);
                else keep(eoe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "InitCmd")) read_init_cmd(eoe.init_cmds.emplace_back(), cc);
                else keep(eoe.extras, cc, prev);
            });
            m.eoe = std::move(eoe);
        } else if (is(name, "SoE")) {
            SoeProtocol soe;
            soe.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "ChannelCount")) soe.channel_count = i32(a, c);
                else if (is(an, "DriveFollowsBit3Support")) soe.drive_follows_bit3_support = boolean(a, c);
                else keep(soe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "InitCmd")) read_init_cmd(soe.init_cmds.emplace_back(), cc);
                else keep(soe.extras, cc, prev);
            });
            m.soe = std::move(soe);
        } else if (is(name, "AoE")) {
            AoeProtocol aoe;
            aoe.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "AdsRouter")) aoe.ads_router = boolean(a, c);
                else if (is(an, "GenerateOwnNetId")) aoe.generate_own_net_id = boolean(a, c);
                else if (is(an, "InitializeOwnNetId")) aoe.initialize_own_net_id = boolean(a, c);
                else keep(aoe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "InitCmd")) read_init_cmd(aoe.init_cmds.emplace_back(), cc);
                else keep(aoe.extras, cc, prev);
            });
            m.aoe = std::move(aoe);
        } else if (is(name, "FoE") || is(name, "VoE")) {
            PlainProtocol p;
            p.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) keep(p.extras, a);
            for_children(c, [&](const pugi::xml_node cc, std::string_view, std::string_view prev) { keep(p.extras, cc, prev); });
            (is(name, "FoE") ? m.foe : m.voe) = std::move(p);
        } else {
            keep(m.extras, c, previous);
        }
    });
}

}  // namespace esi::xml_reader
