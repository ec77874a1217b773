// Rules of the initcmd area: the mailbox commands (CoE SDO downloads, SoE, EoE, AoE) a master
// sends while it moves the device through the EtherCAT state machine.
#include <string>

#include "check/areas.hpp"
#include "check/queries.hpp"
#include "check/rule_cache.hpp"
#include "esi/ethercat/al_state.hpp"
#include "esi/number.hpp"
#include "esi/text_distance.hpp"

namespace esi::rules {

namespace {

struct InitCmdSite {
    const InitCmd* cmd;
    MailboxProtocol protocol;
    const Dictionary* dictionary;  // the dictionary CoE targets live in; null when unknown
};

// Every InitCmd of the document's devices and modules, in document order. A module's commands are
// checked against the module's own Profile/Dictionary only: the device it plugs into is not known.
template <class F>
void for_each_init_cmd(const EsiDocument& document, F&& f) {
    auto visit = [&](const Mailbox& mailbox, const Dictionary* dictionary) {
        mailbox.for_each_init_cmd([&](MailboxProtocol protocol, const InitCmd& c) {
            f(InitCmdSite{&c, protocol, protocol == MailboxProtocol::coe ? dictionary : nullptr});
        });
    };
    for (const auto& info : document.infos) {
        for (const auto& device : info.devices)
            if (device.mailbox) visit(*device.mailbox, device.dictionary());
        for (const auto& module : info.modules) {
            if (!module.mailbox) continue;
            const Dictionary* dictionary = module.profile && module.profile->dictionary ? &*module.profile->dictionary : nullptr;
            visit(*module.mailbox, dictionary);
        }
    }
}

// EtherCAT state machine transitions (ETG.1000.6 §6.4 / ETG.1000.4 ESM), the protocol layer's:
// Init, Pre-Operational, Safe-Operational, Operational, Bootstrap. The item C series and Afag
// SE-Power EtherCAT manuals list the nine without bootstrap (Tabelle 8).
const std::span<const std::string_view> esm_transitions = ethercat::state_machine_transition_names();
// The transitions schema 1.17 allows for InitCmds of every protocol (AoE, EoE, CoE, SoE, module CoE).
constexpr std::string_view init_cmd_transitions[] = {"IP", "PS", "SO", "SP", "OP", "OS"};

bool contains(std::span<const std::string_view> list, std::string_view value) {
    for (std::string_view v : list)
        if (v == value) return true;
    return false;
}

std::string describe(const InitCmdSite& site) {
    std::string text = std::string(to_string(site.protocol)) + " InitCmd";
    if (site.cmd->index) {
        text += " " + format_hex(*site.cmd->index, 4);
        if (site.cmd->subindex) text += ":" + std::to_string(*site.cmd->subindex);
    } else if (site.cmd->idn) {
        text += " IDN " + std::to_string(*site.cmd->idn);
    }
    if (site.cmd->comment && !site.cmd->comment->empty()) text += " ('" + *site.cmd->comment + "')";
    return text;
}

// ---- initcmd-transition-unknown -------------------------------------------------------------

void check_transition_unknown(const EsiDocument& document, RuleContext& context) {
    for_each_init_cmd(document, [&](const InitCmdSite& site) {
        for (const auto& t : site.cmd->transitions) {
            if (contains(esm_transitions, t.text)) continue;
            std::string message = describe(site) + ": Transition '" + t.text + "' is not an EtherCAT state transition";
            std::string upper = t.text;
            for (char& c : upper)
                if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
            const std::string suggestion = contains(esm_transitions, upper) ? upper : closest_match(t.text, init_cmd_transitions);
            if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
            else message += " (IP, PS, SP, SO, OS, OP)";
            context.report(t.pos, std::move(message));
        }
    });
}

constexpr Rule initcmd_transition_unknown{
    .id = "initcmd-transition-unknown",
    .default_severity = Severity::error,
    .summary = "InitCmd Transition that is not an EtherCAT state transition",
    .rationale =
        "A Transition names the state change at which the master sends the command: two letters from I (Init), P "
        "(Pre-Operational), S (Safe-Operational), O (Operational), B (Bootstrap), e.g. PS = Pre-Op -> Safe-Op "
        "(ETG.1000.6 state machine; ETG.2000 InitCmd; the item C series and Afag SE-Power EtherCAT manuals, §6.2 "
        "Tabelle 8 and §6.7.4). Anything else, including lower case, matches no transition, so the master never sends "
        "the command; the schema enumeration rejects it (leducp/KickCAT reports 'unknown transition').",
    .bad_example =
        "<InitCmd><Transition>PO</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>",
    .good_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>",
    .check = check_transition_unknown,
};

// ---- initcmd-transition-not-allowed ---------------------------------------------------------

std::string_view transition_reason(std::string_view t) {
    if (t == "IB" || t == "BI") return "bootstrap transitions use the bootstrap mailbox, which carries FoE only";
    return "a command on the way down to Init is not part of the schema's start-up list, and masters do not send it";
}

void check_transition_not_allowed(const EsiDocument& document, RuleContext& context) {
    for_each_init_cmd(document, [&](const InitCmdSite& site) {
        for (const auto& t : site.cmd->transitions) {
            if (!contains(esm_transitions, t.text) || contains(init_cmd_transitions, t.text)) continue;
            context.report(t.pos, describe(site) + ": Transition '" + t.text + "' is a state transition, but InitCmds " +
                                      "may only run at IP, PS, SP, SO, OS or OP (ETG.2000 schema); " +
                                      std::string(transition_reason(t.text)));
        }
    });
}

constexpr Rule initcmd_transition_not_allowed{
    .id = "initcmd-transition-not-allowed",
    .default_severity = Severity::warning,
    .summary = "InitCmd at a transition the schema does not allow (PI, SI, OI, IB, BI)",
    .rationale =
        "Schema 1.17 allows InitCmd transitions IP, PS, SO, SP, OP and OS for every protocol (AoE, EoE, CoE, SoE). "
        "The manuals of the item C series and Afag SE-Power servo controllers list all nine state-machine transitions "
        "(IP, PI, PS, SP, SO, OS, OP, SI, OI; Tabelle 8 and 15) because their Transition column refers to the state "
        "machine, but the transitions down to Init (PI, SI, OI) are not start-up steps, and Bootstrap transitions "
        "(IB, BI) run on the bootstrap mailbox, which carries FoE only. Masters that follow the schema never send "
        "such a command, so it is reported as a warning rather than an error: the value is a real transition, but the "
        "command silently does nothing.",
    .bad_example =
        "<InitCmd><Transition>PI</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>",
    .good_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>",
    .check = check_transition_not_allowed,
};

// ---- initcmd-transition-missing -------------------------------------------------------------

void check_transition_missing(const EsiDocument& document, RuleContext& context) {
    for_each_init_cmd(document, [&](const InitCmdSite& site) {
        if (!site.cmd->transitions.empty()) return;
        context.report(site.cmd->pos, describe(site) + " has no Transition, so a master never sends it");
    });
}

constexpr Rule initcmd_transition_missing{
    .id = "initcmd-transition-missing",
    .default_severity = Severity::error,
    .summary = "InitCmd without Transition",
    .rationale =
        "Transition is required (maxOccurs unbounded, at least one): without it the master does not know when to send "
        "the command, and it is never sent (ETG.2000 InitCmd; leducp/KickCAT rejects 'InitCmd without "
        "Transition').",
    .bad_example = "<InitCmd><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>",
    .good_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>",
    .check = check_transition_missing,
};

// ---- initcmd-data-hex -----------------------------------------------------------------------

void check_data_hex(const EsiDocument& document, RuleContext& context) {
    for_each_init_cmd(document, [&](const InitCmdSite& site) {
        const InitCmd& cmd = *site.cmd;
        if (!cmd.has_data || cmd.data.valid()) return;
        const bool odd = cmd.data.text.size() % 2 != 0;
        std::string message = describe(site) + ": Data '" + cmd.data.text + "' ";
        if (odd) {
            bool digits = true;
            for (char c : cmd.data.text)
                digits = digits && ((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'));
            message += digits ? "has an odd number of hex digits; Data is hexBinary, two digits per byte (write '0" +
                                    cmd.data.text + "')"
                              : "is not hexBinary (two hex digits per byte)";
        } else {
            message += "is not hexBinary (two hex digits per byte, no prefix)";
        }
        context.report(cmd.data.pos.known() ? cmd.data.pos : cmd.pos, std::move(message));
    });
}

constexpr Rule initcmd_data_hex{
    .id = "initcmd-data-hex",
    .default_severity = Severity::error,
    .summary = "InitCmd Data that is not even-length hexBinary",
    .rationale =
        "InitCmd Data is xs:hexBinary: two hex digits per byte, no prefix, written in the byte order of the SDO "
        "(little-endian for numbers). An odd number of digits has no byte reading: the example in §7 of the item C "
        "series and Afag SE-Power EtherCAT manuals writes the 16-bit Controlword 0x6040 with `<Data>0</Data>`, which "
        "tools pad, truncate or reject differently (leducp/KickCAT: 'odd-length hex binary').",
    .bad_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6040</Index><SubIndex>0</SubIndex><Data>0</Data></InitCmd>",
    .good_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6040</Index><SubIndex>0</SubIndex><Data>0000</Data></InitCmd>",
    .check = check_data_hex,
};

// ---- initcmd-target-missing -----------------------------------------------------------------

// CoE InitCmds whose target can be looked up: a dictionary exists and the index is absolute
// (IndexDependOnSlot adds a slot offset the description alone does not fix).
template <class F>
void for_each_coe_target(const EsiDocument& document, RuleContext& context, F&& f) {
    for_each_init_cmd(document, [&](const InitCmdSite& site) {
        if (site.protocol != MailboxProtocol::coe || !site.dictionary || !site.cmd->index) return;
        if ((site.cmd->index_depend_on_slot && *site.cmd->index_depend_on_slot) ||
            (site.cmd->index_depend_on_slot_group && *site.cmd->index_depend_on_slot_group))
            return;
        f(site, context.cache().objects(site.dictionary));
    });
}

void check_target_missing(const EsiDocument& document, RuleContext& context) {
    for_each_coe_target(document, context, [&](const InitCmdSite& site, const DictionaryIndex& index) {
        const std::uint32_t object_index = *site.cmd->index;
        const Object* object = index.object(object_index);
        if (!object) {
            context.report(site.cmd->pos, describe(site) + " writes object " + format_hex(object_index, 4) +
                                              ", which the Dictionary does not list; either the offline dictionary is "
                                              "incomplete or the slave answers with SDO abort 0x06020000 'object does "
                                              "not exist'");
            return;
        }
        const std::uint32_t subindex = site.cmd->subindex.value_or(0);
        if (site.cmd->complete_access && *site.cmd->complete_access && subindex <= 1) return;
        const ObjectLayout* layout = index.layout(object_index);
        if (!layout || layout->entry(subindex)) return;
        std::uint32_t highest = 0;
        for (const auto& e : layout->entries) highest = std::max(highest, e.subindex);
        context.report(site.cmd->pos, describe(site) + " writes sub-index " + std::to_string(subindex) + " of " +
                                          format_hex(object_index, 4) + " '" + primary_text(object->names) +
                                          "', which has sub-indices 0.." + std::to_string(highest) +
                                          " in the Dictionary; either the offline dictionary is incomplete or the slave "
                                          "answers with SDO abort 0x06090011 'subindex does not exist'",
                       {context.note(object->pos, "the object")});
    });
}

constexpr Rule initcmd_target_missing{
    .id = "initcmd-target-missing",
    .default_severity = Severity::warning,
    .summary = "CoE InitCmd writing an object or sub-index the Dictionary lacks",
    .rationale =
        "A CoE InitCmd is an SDO download to Index:SubIndex. When the device's Dictionary does not have the target, "
        "the slave answers with abort 0x06020000 or 0x06090011 and the master stops the state change "
        "(OpenEtherCATsociety/SOEM #402 'index:0016.00 error:06020000 The object does not exist'; ETG.1000.6 SDO "
        "abort codes). Checked only when the device (or module) has a Dictionary; commands whose index depends on the "
        "slot are skipped. A warning, not an error: ESI dictionaries are offline copies that vendors sometimes trim "
        "(Beckhoff AX2000 writes 0x60C2 at start-up but lists no 0x60C2), so either the command or the dictionary is "
        "wrong.",
    .bad_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6061</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd> "
        "(no object 0x6061)",
    .good_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>",
    .check = check_target_missing,
};

// Types whose value has a fixed size: a shorter download is refused (SDO abort 0x06070013).
bool fixed_size(const ObjectEntry& entry) {
    if (!entry.basic) return false;
    switch (entry.basic->type_class) {
        case TypeClass::boolean:
        case TypeClass::bit:
        case TypeClass::signed_integer:
        case TypeClass::unsigned_integer:
        case TypeClass::real:
        case TypeClass::bit_string: return true;
        default: return false;
    }
}

// ---- initcmd-data-length --------------------------------------------------------------------

void check_data_length(const EsiDocument& document, RuleContext& context) {
    for_each_coe_target(document, context, [&](const InitCmdSite& site, const DictionaryIndex& index) {
        const InitCmd& cmd = *site.cmd;
        if (!cmd.has_data || !cmd.data.valid()) return;
        const Object* object = index.object(*cmd.index);
        if (!object) return;
        const std::uint64_t bytes = cmd.data.byte_length();
        const SourcePos at = cmd.data.pos.known() ? cmd.data.pos : cmd.pos;
        if (cmd.complete_access && *cmd.complete_access) {
            // Complete access writes the whole object from sub-index 0 or 1 on; BitSize covers it all.
            const std::uint64_t object_bytes = (object->bit_size + 7) / 8;
            if (object->bit_size == 0 || bytes <= object_bytes) return;
            context.report(at, describe(site) + ": Data has " + std::to_string(bytes) + " bytes, more than the whole object " +
                                   format_hex(*cmd.index, 4) + " (" + std::to_string(object_bytes) + " bytes, BitSize " +
                                   std::to_string(object->bit_size) + ") a complete access can write",
                           {context.note(object->pos, "the object")});
            return;
        }
        const ObjectLayout* layout = index.layout(*cmd.index);
        const ObjectEntry* entry = layout ? layout->entry(cmd.subindex.value_or(0)) : nullptr;
        if (!entry || entry->bit_size == 0) return;
        const std::uint64_t entry_bytes = (entry->bit_size + 7) / 8;
        if (bytes == entry_bytes || (bytes < entry_bytes && !fixed_size(*entry))) return;
        context.report(at,
                       describe(site) + ": Data has " + std::to_string(bytes) + " byte" + (bytes == 1 ? "" : "s") + " but " +
                           format_hex(*cmd.index, 4) + ":" + std::to_string(entry->subindex) + " '" + entry->name + "' is " +
                           (entry->type.empty() ? std::string() : entry->type + ", ") + std::to_string(entry->bit_size) +
                           " bits (" + std::to_string(entry_bytes) + " byte" + (entry_bytes == 1 ? "" : "s") +
                           "); the slave answers with SDO abort 0x0607001" + (bytes > entry_bytes ? "2 'length too high'" : "3 'length too low'"),
                       {context.note(object->pos, "the object")});
    });
}

constexpr Rule initcmd_data_length{
    .id = "initcmd-data-length",
    .default_severity = Severity::error,
    .summary = "InitCmd Data longer (or, for numbers, shorter) than the target",
    .rationale =
        "An SDO download must carry exactly the size of a numeric target; the slave refuses other lengths with abort "
        "0x06070012 (too long) or 0x06070013 (too short) and the master stops the start-up (ETG.1000.6 SDO abort "
        "codes). Strings and domains may be shorter. With CompleteAccess the data may fill the whole object, so it is "
        "compared with the object's BitSize. Checked when the device has a Dictionary (the item C series and Afag "
        "SE-Power EtherCAT manuals write the 16-bit Controlword with a 1-digit Data in §7 and limit SDOs to 4 bytes "
        "in §6.3 and Tabelle 15).",
    .bad_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>0300</Data></InitCmd> "
        "(0x6060 is SINT)",
    .good_example =
        "<InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>03</Data></InitCmd>",
    .check = check_data_length,
};

// ---- initcmd-read-only-target ---------------------------------------------------------------

// The Dictionary's access of an object entry: the SubItem's flags, else the object's.
bool read_only(const ObjectEntry& entry) {
    if (!entry.flags || !entry.flags->access) return false;
    const std::string_view access = trim(*entry.flags->access);
    return access == "ro" || access == "const";
}

void check_read_only_target(const EsiDocument& document, RuleContext& context) {
    for_each_coe_target(document, context, [&](const InitCmdSite& site, const DictionaryIndex& index) {
        const InitCmd& cmd = *site.cmd;
        // Complete access writes a whole record, whose sub-index 0 is read-only by nature.
        if (cmd.complete_access.value_or(false)) return;
        const Object* object = index.object(*cmd.index);
        const ObjectLayout* layout = object ? index.layout(*cmd.index) : nullptr;
        const ObjectEntry* entry = layout ? layout->entry(cmd.subindex.value_or(0)) : nullptr;
        if (!entry || !read_only(*entry)) return;
        context.report(cmd.pos, describe(site) + " writes " + format_hex(*cmd.index, 4) + ":" + std::to_string(entry->subindex) + " '" +
                                    entry->name + "', which the Dictionary marks " + std::string(trim(*entry->flags->access)) +
                                    "; either the offline access flags are stale or the slave answers with SDO abort "
                                    "0x06010002 'attempt to write a read only object'",
                       {context.note(entry->flags->pos.known() ? entry->flags->pos : object->pos, "the access is declared here")});
    });
}

constexpr Rule initcmd_read_only_target{
    .id = "initcmd-read-only-target",
    .default_severity = Severity::warning,
    .summary = "A CoE InitCmd writes an object entry the Dictionary marks read-only",
    .rationale =
        "A CoE InitCmd is an SDO download; an object whose access is ro (or const) refuses it with abort 0x06010002 "
        "'attempt to write a read only object', and the master stops the start-up (ETG.1000.6 SDO abort codes; "
        "ETG.2000 ObjectType Flags/Access, the SubItem's flags before the object's). The offline access flags are "
        "stale often enough that the rule cannot tell which side is wrong (Beckhoff AX2000-B110 writes 0x6060 Modes "
        "of operation, read-write in CiA 402, while its Dictionary says ro): a warning. Complete-access commands are "
        "not checked, as a record's sub-index 0 is read-only by nature.",
    .bad_example =
        "<Object><Index>#x6061</Index>…<Flags><Access>ro</Access></Flags></Object> … "
        "<InitCmd><Transition>PS</Transition><Index>#x6061</Index><SubIndex>0</SubIndex><Data>08</Data></InitCmd>",
    .good_example =
        "<Object><Index>#x6060</Index>…<Flags><Access>rw</Access></Flags></Object> … "
        "<InitCmd><Transition>PS</Transition><Index>#x6060</Index><SubIndex>0</SubIndex><Data>08</Data></InitCmd>",
    .check = check_read_only_target,
};

// ---- initcmd-pdo-transition -----------------------------------------------------------------

// The PDO assignment (0x1C12, 0x1C13) and mapping objects (RxPDO 0x1600-0x17FF, TxPDO
// 0x1A00-0x1BFF) of ETG.1000.6.
bool is_pdo_configuration(std::uint32_t index) {
    return index == 0x1C12 || index == 0x1C13 || (index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF);
}

// Transitions whose commands the master sends while the device is in Pre-Operational.
bool sent_in_pre_operational(std::string_view transition) { return transition == "IP" || transition == "PS"; }

void check_pdo_transition(const EsiDocument& document, RuleContext& context) {
    for_each_init_cmd(document, [&](const InitCmdSite& site) {
        if (site.protocol != MailboxProtocol::coe || !site.cmd->index || !is_pdo_configuration(*site.cmd->index)) return;
        for (const auto& t : site.cmd->transitions) {
            // Unknown transitions and those down to Init or into Bootstrap, which masters do not
            // send, are the other initcmd-transition rules' findings.
            if (sent_in_pre_operational(t.text) || !contains(init_cmd_transitions, t.text)) continue;
            context.report(t.pos, describe(site) + " configures PDOs at transition " + t.text +
                                      "; the PDO assignment and mapping can only be written in Pre-Operational (IP or PS), "
                                      "and the slave answers with SDO abort 0x08000022 so the transition fails");
        }
    });
}

constexpr Rule initcmd_pdo_transition{
    .id = "initcmd-pdo-transition",
    .default_severity = Severity::error,
    .summary = "An InitCmd writes the PDO assignment or mapping outside Pre-Operational (not at IP or PS)",
    .rationale =
        "The PDO assignment objects 0x1C12/0x1C13 and the mapping objects 0x1600-0x17FF/0x1A00-0x1BFF may only be "
        "changed in Pre-Operational; in Safe-Operational and Operational the process data are running and the slave "
        "refuses the download with SDO abort 0x08000022 'data cannot be transferred or stored because of the present "
        "device state' (ETG.1000.6 PDO mapping and assignment, SDO abort codes; SOES soes/esc_coe.c answers so for "
        "objects writable in Pre-Operational only, ATYPE_RWpre, as its applications declare the PDO objects). Commands at IP and PS are sent while the device is in "
        "Pre-Operational; at SP, SO, OS or OP the master stops the start-up with the abort.",
    .bad_example =
        "<InitCmd><Transition>SO</Transition><Index>#x1C12</Index><SubIndex>0</SubIndex><Data>00</Data></InitCmd>",
    .good_example =
        "<InitCmd><Transition>PS</Transition><Index>#x1C12</Index><SubIndex>0</SubIndex><Data>00</Data></InitCmd>",
    .check = check_pdo_transition,
};

// ---- initcmd-complete-access-unsupported ----------------------------------------------------

void check_complete_access_unsupported(const EsiDocument& document, RuleContext& context) {
    // Devices only: a module's commands go to the device it is plugged into, whose CoE element
    // declares complete access, and that device is not known here.
    for (const Device* device : context.cache().devices(document)) {
        if (!device->mailbox || !device->mailbox->coe) continue;
        const CoeProtocol& coe = *device->mailbox->coe;
        if (coe.complete_access.value_or(false)) continue;
        for (const InitCmd& cmd : coe.init_cmds) {
            if (!cmd.complete_access.value_or(false)) continue;
            const InitCmdSite site{&cmd, MailboxProtocol::coe, nullptr};
            context.report(cmd.pos, describe(site) + " uses complete access, but the device's CoE element " +
                                        (coe.complete_access ? "says CompleteAccess=\"false\"" : "does not declare CompleteAccess") +
                                        "; the device refuses the download (SDO abort 0x06010004) and the start-up stops. "
                                        "Declare CompleteAccess=\"true\" or write the sub-indices one by one",
                           {context.note(coe.pos, "the CoE element")});
        }
    }
}

constexpr Rule initcmd_complete_access_unsupported{
    .id = "initcmd-complete-access-unsupported",
    .default_severity = Severity::error,
    .summary = "A CoE InitCmd with complete access on a device that does not declare CompleteAccess",
    .rationale =
        "CoE@CompleteAccess says whether the device serves SDO complete access (ETG.2000 CoE; the SII General "
        "category copies it as CoE detail bit 5, ETG.2010). An InitCmd with CompleteAccess=\"true\" makes the master "
        "send an SDO download with the complete-access bit (ETG.1000.6 SDO initiate download, bit 4); a device "
        "without the service answers with abort 0x06010004 'object cannot be accessed with complete access' and the "
        "master stops the state change. The attribute defaults to false, so leaving it out declares no support.",
    .bad_example = "<CoE SdoInfo=\"true\"><InitCmd CompleteAccess=\"true\"><Transition>PS</Transition><Index>#x1C12</Index>"
                   "…</InitCmd></CoE>",
    .good_example = "<CoE SdoInfo=\"true\" CompleteAccess=\"true\"><InitCmd CompleteAccess=\"true\"><Transition>PS</"
                    "Transition><Index>#x1C12</Index>…</InitCmd></CoE>",
    .check = check_complete_access_unsupported,
};

}  // namespace

void add_initcmd(std::vector<Rule>& out) {
    out.insert(out.end(), {
        initcmd_transition_unknown,
        initcmd_transition_not_allowed,
        initcmd_transition_missing,
        initcmd_data_hex,
        initcmd_data_length,
        initcmd_target_missing,
        initcmd_read_only_target,
        initcmd_pdo_transition,
        initcmd_complete_access_unsupported,
    });
}

}  // namespace esi::rules
