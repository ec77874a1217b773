#pragma once
// Mailbox element: protocols, CoE flags and the InitCmds a master sends on state transitions.

#include "esi/model/common.hpp"
#include "esi/model/mailbox_protocol.hpp"

namespace esi {

struct Transition {
    std::string text;  // IP, PS, SP, SO, OS, OP, SI, OI, PI, IB, BI …
    SourcePos pos;
};

// One InitCmd. Which fields are used depends on the protocol:
// CoE: Index, SubIndex, Data; SoE: IDN, Data (+@Chn); EoE: Type, Data; AoE: Data.
struct InitCmd {
    std::vector<Transition> transitions;
    std::optional<std::uint32_t> index;
    std::optional<bool> index_depend_on_slot;
    std::optional<bool> index_depend_on_slot_group;
    std::optional<std::uint32_t> subindex;
    std::optional<std::int64_t> idn;   // SoE
    std::optional<std::int64_t> type;  // EoE
    HexData data;
    bool has_data = false;
    std::optional<bool> data_adapt_automatically;
    std::optional<std::string> comment;
    std::optional<bool> fixed;
    std::optional<bool> complete_access;
    std::optional<bool> overwritten_by_module;
    std::optional<std::int32_t> channel;  // SoE @Chn
    SourcePos pos;
    Extras extras;
};

struct CoeProtocol {
    std::optional<bool> sdo_info;
    std::optional<bool> pdo_assign;
    std::optional<bool> pdo_config;
    std::optional<bool> pdo_upload;
    std::optional<bool> complete_access;
    std::optional<bool> segmented_sdo;
    std::optional<bool> diag_history;
    std::optional<bool> sdo_upload_with_max_length;
    std::optional<bool> time_distribution;
    std::optional<bool> module_od;  // modules only
    std::optional<std::string> eds_file;
    std::optional<std::int32_t> ds402_channels;
    std::vector<InitCmd> init_cmds;
    SourcePos pos;
    Extras extras;  // e.g. CoE/Object
};

struct EoeProtocol {
    std::optional<bool> ip;
    std::optional<bool> mac;
    std::optional<bool> time_stamp;
    std::vector<InitCmd> init_cmds;
    SourcePos pos;
    Extras extras;
};

struct SoeProtocol {
    std::optional<std::int32_t> channel_count;
    std::optional<bool> drive_follows_bit3_support;
    std::vector<InitCmd> init_cmds;
    SourcePos pos;
    Extras extras;  // DiagFile, DiagMessages …
};

struct AoeProtocol {
    std::optional<bool> ads_router;
    std::optional<bool> generate_own_net_id;
    std::optional<bool> initialize_own_net_id;
    std::vector<InitCmd> init_cmds;
    SourcePos pos;
    Extras extras;
};

// FoE and VoE carry no typed content.
struct PlainProtocol {
    SourcePos pos;
    Extras extras;
};

struct Mailbox {
    std::optional<bool> data_link_layer;
    std::optional<bool> real_time_mode;
    std::optional<AoeProtocol> aoe;
    std::optional<EoeProtocol> eoe;
    std::optional<CoeProtocol> coe;
    std::optional<PlainProtocol> foe;
    std::optional<SoeProtocol> soe;
    std::optional<PlainProtocol> voe;
    SourcePos pos;
    Extras extras;

    [[nodiscard]] bool has(MailboxProtocol protocol) const;
    // SII word 0x1C bits: AoE 0x01, EoE 0x02, CoE 0x04, FoE 0x08, SoE 0x10, VoE 0x20.
    [[nodiscard]] std::uint16_t protocol_bits() const;
    // The protocol's InitCmds; null when the mailbox has no such protocol or it carries none
    // (FoE, VoE).
    [[nodiscard]] const std::vector<InitCmd>* init_cmds(MailboxProtocol protocol) const;
    // Calls f(protocol, cmd) for every InitCmd: the protocols in init_cmd_protocols order, the
    // commands of each in document order.
    template <class F>
    void for_each_init_cmd(F&& f) const {
        for (const MailboxProtocol protocol : init_cmd_protocols)
            if (const std::vector<InitCmd>* cmds = init_cmds(protocol))
                for (const InitCmd& cmd : *cmds) f(protocol, cmd);
    }
};

}  // namespace esi
