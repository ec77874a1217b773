// Rules of the mailbox area: the Mailbox element of a device, its protocols and the SMs it needs.
#include <string>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "check/queries.hpp"
#include "check/sm_roles.hpp"

namespace esi::rules {

namespace {

// ---- mailbox-data-link-layer ----------------------------------------------------------------

void check_data_link_layer(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->mailbox) continue;
        const Mailbox& mailbox = *device->mailbox;
        if (mailbox.data_link_layer && *mailbox.data_link_layer) continue;
        context.report(mailbox.pos, std::string("Mailbox ") +
                                        (mailbox.data_link_layer ? "has DataLinkLayer=\"false\"" : "does not set DataLinkLayer") +
                                        "; devices with a mailbox are expected to support the mailbox data link layer "
                                        "(repeat request and counter) and to declare it with DataLinkLayer=\"true\"");
    }
}

constexpr Rule mailbox_data_link_layer{
    .id = "mailbox-data-link-layer",
    .default_severity = Severity::warning,
    .summary = "Mailbox without DataLinkLayer=\"true\"",
    .rationale =
        "The mailbox data link layer (counter and repeat request, ETG.1000.4 mailbox) lets a master recover lost "
        "mailbox frames; the conformance tool checks that devices with a mailbox declare it (CTT TF-1300 1-9 "
        "'Device:Mailbox:DataLinkLayer'), the SOES tutorial marks the attribute mandatory, and the SII general "
        "category carries it as flag MBoxDataLinkLayer (ETG.2010). The schema default is false, so leaving it out "
        "declares no support.",
    .bad_example = "<Mailbox><CoE SdoInfo=\"true\"/></Mailbox>",
    .good_example = "<Mailbox DataLinkLayer=\"true\"><CoE SdoInfo=\"true\"/></Mailbox>",
    .check = check_data_link_layer,
};

// ---- mailbox-sm-disabled --------------------------------------------------------------------

void check_sm_disabled(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->mailbox || device->mailbox->protocol_bits() == 0) continue;
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            const SmRole role = device_sm_role(*device, sm);
            if (role != SmRole::mailbox_out && role != SmRole::mailbox_in) continue;
            if (!sm.enable || (*sm.enable & 1) != 0) continue;
            context.report(sm.pos, "SM" + std::to_string(n) + " '" + sm.type + "' is a mailbox SM with Enable=\"" +
                                       std::to_string(*sm.enable) +
                                       "\"; masters program the mailbox SMs with this enable bit (SII SyncM category), "
                                       "so the mailbox never receives or answers. Write Enable=\"1\"",
                           {context.note(device->mailbox->pos, "the Mailbox whose protocols need it")});
        }
    }
}

constexpr Rule mailbox_sm_disabled{
    .id = "mailbox-sm-disabled",
    .default_severity = Severity::error,
    .summary = "A mailbox SM with Enable=\"0\" on a device whose Mailbox names protocols",
    .rationale =
        "Sm@Enable becomes the enable byte of the SII SyncM category (ETG.2010), and masters program SM0/SM1 with it "
        "at INIT -> PRE-OP: SOEM's ecx_config_init copies the SII control byte and enable byte into the mailbox SMs' "
        "registers (0x0804-0x0806 + 8n) as they are. A disabled mailbox SM takes no requests, so every mailbox "
        "protocol the Mailbox element declares (CoE, FoE, EoE …) times out and a device whose configuration needs "
        "SDOs never reaches SAFE-OP. Process-data SMs may start disabled (their length comes from the PDOs); a "
        "mailbox SM may not.",
    .bad_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"0\">MBoxOut</Sm>",
    .good_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>",
    .check = check_sm_disabled,
};

// ---- mailbox-sm-missing ---------------------------------------------------------------------

void check_sm_missing(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        // A Mailbox that names no protocol declares nothing to carry (mailbox-protocol-missing).
        if (!device->mailbox || device->mailbox->protocol_bits() == 0) continue;
        bool has_out = false;
        bool has_in = false;
        for (const auto& sm : device->sms) {
            const SmRole role = device_sm_role(*device, sm);
            has_out = has_out || role == SmRole::mailbox_out;
            has_in = has_in || role == SmRole::mailbox_in;
        }
        if (has_out && has_in) continue;
        const std::string missing = !has_out && !has_in ? "neither an MBoxOut nor an MBoxIn Sm"
                                    : !has_out        ? "no MBoxOut Sm (master -> slave)"
                                                      : "no MBoxIn Sm (slave -> master)";
        context.report(device->mailbox->pos, "the device declares a Mailbox but has " + missing +
                                                 "; mailbox protocols need SM0 = MBoxOut (#x26) and SM1 = MBoxIn (#x22)");
    }
}

constexpr Rule mailbox_sm_missing{
    .id = "mailbox-sm-missing",
    .default_severity = Severity::error,
    .summary = "A Mailbox without MBoxOut and MBoxIn SyncManagers",
    .rationale =
        "Mailbox protocols travel through the standard mailbox: SM0 (MBoxOut, master -> slave) and SM1 (MBoxIn, slave "
        "-> master), whose addresses and sizes also fill SII words 0x18-0x1B (ETG.2010; SOES tutorial; the item C "
        "series and Afag SE-Power EtherCAT manuals, §6.1.1 and Tabelle 5). A Mailbox element without them advertises "
        "protocols the master cannot reach. An empty <Mailbox/> names no protocol, so it needs no mailbox SMs "
        "(mailbox-protocol-missing reports it).",
    .bad_example = "<Sm ...>Outputs</Sm><Sm ...>Inputs</Sm><Mailbox DataLinkLayer=\"true\"><CoE/></Mailbox>",
    .good_example =
        "<Sm ... ControlByte=\"#x26\">MBoxOut</Sm><Sm ... ControlByte=\"#x22\">MBoxIn</Sm>...<Mailbox "
        "DataLinkLayer=\"true\"><CoE/></Mailbox>",
    .check = check_sm_missing,
};

// ---- mailbox-protocol-missing ---------------------------------------------------------------

void check_protocol_missing(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->mailbox || device->mailbox->protocol_bits() != 0) continue;
        context.report(device->mailbox->pos,
                       "Mailbox names no protocol (AoE, EoE, CoE, FoE, SoE, VoE); the SII mailbox protocol word 0x1C would "
                       "be 0 and masters would not use the mailbox");
    }
}

constexpr Rule mailbox_protocol_missing{
    .id = "mailbox-protocol-missing",
    .default_severity = Severity::warning,
    .summary = "A Mailbox that names no protocol",
    .rationale =
        "The protocols listed under Mailbox (AoE, EoE, CoE, FoE, SoE, VoE) become the SII mailbox protocol word 0x1C "
        "(ETG.2010; CTT TF-1300 2-5 compares them). An empty Mailbox advertises a mailbox that carries nothing, so "
        "masters skip it; either list the protocols the firmware serves or remove the element.",
    .bad_example = "<Mailbox DataLinkLayer=\"true\"/>",
    .good_example = "<Mailbox DataLinkLayer=\"true\"><CoE SdoInfo=\"true\"/></Mailbox>",
    .check = check_protocol_missing,
};

}  // namespace

void add_mailbox(std::vector<Rule>& out) {
    out.insert(out.end(), {
        mailbox_data_link_layer,
        mailbox_sm_missing,
        mailbox_sm_disabled,
        mailbox_protocol_missing,
    });
}

}  // namespace esi::rules
