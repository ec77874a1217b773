// Rules of the fmmu area. An FMMU maps a range of the master's logical process image onto ESC
// memory; the Fmmu elements say what each of the device's FMMUs is for, and the SII FMMU
// category (ETG.2010, category 40) encodes that use as one byte: 1 Outputs, 2 Inputs,
// 3 SyncM status (MBoxState), 0 unused.
#include <string>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "check/esc_controller.hpp"
#include "check/queries.hpp"
#include "check/sm_roles.hpp"
#include "esi/text_distance.hpp"

namespace esi::rules {

namespace {

// The schema leaves the text free; ETG.2000 names Outputs, Inputs and MBoxState, and Beckhoff's
// AX5xxx drives add DynamicOutputs/DynamicInputs, which SII writers store as Outputs/Inputs.
constexpr std::string_view known_types[] = {"Outputs", "Inputs", "MBoxState", "DynamicInputs", "DynamicOutputs"};

SmRole fmmu_sm_role(std::string_view type) {
    if (type == "Outputs" || type == "DynamicOutputs") return SmRole::outputs;
    if (type == "Inputs" || type == "DynamicInputs") return SmRole::inputs;
    if (type == "MBoxState") return SmRole::mailbox_in;
    return SmRole::unknown;
}

std::string fmmu_label(const Fmmu& fmmu, std::size_t number) {
    return "FMMU" + std::to_string(number) + (fmmu.type.empty() ? std::string() : " '" + fmmu.type + "'");
}

// ---- fmmu-type-unknown ----------------------------------------------------------------------

void check_type(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        for (std::size_t n = 0; n < device->fmmus.size(); ++n) {
            const Fmmu& fmmu = device->fmmus[n];
            // An empty Fmmu is an unused FMMU (SII FMMU category value 0), as Beckhoff writes <Fmmu/>.
            if (fmmu.type.empty() || fmmu_sm_role(fmmu.type) != SmRole::unknown) continue;
            std::string message = "FMMU" + std::to_string(n) + " has type '" + fmmu.type +
                                  "', which is none of Outputs, Inputs, MBoxState, DynamicInputs, DynamicOutputs; SII "
                                  "writers cannot encode it";
            const std::string suggestion = closest_match(fmmu.type, known_types);
            if (!suggestion.empty()) message += " (did you mean '" + suggestion + "'?)";
            context.report(fmmu.pos, std::move(message));
        }
    }
}

constexpr Rule fmmu_type_unknown{
    .id = "fmmu-type-unknown",
    .default_severity = Severity::error,
    .summary = "Fmmu text that is not an FMMU use",
    .rationale =
        "The Fmmu text says what the FMMU maps: Outputs, Inputs or MBoxState (and Beckhoff's DynamicOutputs/"
        "DynamicInputs). The SII FMMU category stores exactly these as 1, 2, 3 (0 unused), so any other text cannot "
        "be written to the EEPROM and masters do not know how to use the FMMU (ETG.2000 Fmmu; ETG.2010 category 40; "
        "CTT TF-1300 2-11 compares them).",
    .bad_example = "<Fmmu>Output</Fmmu>",
    .good_example = "<Fmmu>Outputs</Fmmu>",
    .check = check_type,
};

// ---- fmmu-sm-reference ----------------------------------------------------------------------

void check_sm_reference(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        for (std::size_t n = 0; n < device->fmmus.size(); ++n) {
            const Fmmu& fmmu = device->fmmus[n];
            if (!fmmu.sm) continue;
            if (*fmmu.sm >= device->sms.size()) {
                context.report(fmmu.pos, fmmu_label(fmmu, n) + " names Sm " + std::to_string(*fmmu.sm) + " but the device has " +
                                             std::to_string(device->sms.size()) + " Sm element" +
                                             (device->sms.size() == 1 ? "" : "s"));
                continue;
            }
            const SmRole wanted = fmmu_sm_role(fmmu.type);
            const SyncManager& sm = device->sms[*fmmu.sm];
            const SmRole role = device_sm_role(*device, sm);
            if (wanted == SmRole::unknown || role == SmRole::unknown || role == wanted) continue;
            context.report(fmmu.pos,
                           fmmu_label(fmmu, n) + " maps SM" + std::to_string(*fmmu.sm) +
                               (sm.type.empty() ? std::string() : " '" + sm.type + "'") + ", which is " +
                               std::string(to_string(role)) + "; an " + fmmu.type + " FMMU needs an " +
                               std::string(to_string(wanted)) + " SyncManager",
                           {context.note(sm.pos, "the SyncManager")});
        }
    }
}

constexpr Rule fmmu_sm_reference{
    .id = "fmmu-sm-reference",
    .default_severity = Severity::error,
    .summary = "Fmmu@Sm names a missing SM or one of the other direction",
    .rationale =
        "Fmmu@Sm ties the FMMU to a SyncManager (the n-th Sm element). An Outputs FMMU must map an output SM, an "
        "Inputs FMMU an input SM and MBoxState the mailbox-in SM whose status bit it maps; a reference to a missing "
        "or opposite SM makes masters that follow it map the wrong memory (ETG.2000 Fmmu@Sm; ethercrab-rs/ethercrab "
        "#287 falls back to the SM index when the mapping cannot be resolved).",
    .bad_example = "<Fmmu Sm=\"3\">Outputs</Fmmu> ... (SM3 is Inputs)",
    .good_example = "<Fmmu Sm=\"2\">Outputs</Fmmu> ... (SM2 is Outputs)",
    .check = check_sm_reference,
};

// ---- fmmu-missing ---------------------------------------------------------------------------

// Whether a process-data SM will carry data: a size, or PDOs assigned to it by default.
bool carries_data(const Device& device, std::size_t number) {
    const SyncManager& sm = device.sms[number];
    if (sm.default_size && *sm.default_size > 0) return true;
    for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
        for (const auto& pdo : *list)
            if (pdo.sm && *pdo.sm == number && pdo.bit_size() > 0) return true;
    return false;
}

void check_missing(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        bool has_outputs_fmmu = false;
        bool has_inputs_fmmu = false;
        for (const auto& fmmu : device->fmmus) {
            const SmRole role = fmmu_sm_role(fmmu.type);
            has_outputs_fmmu = has_outputs_fmmu || role == SmRole::outputs;
            has_inputs_fmmu = has_inputs_fmmu || role == SmRole::inputs;
        }
        // An FMMU without a known use (empty, as in Beckhoff's early <Fmmu/> lists, or vendor text, which
        // gets fmmu-type-unknown) may be the one the master uses for this data: do not guess.
        bool has_unknown_fmmu = false;
        for (const auto& fmmu : device->fmmus) has_unknown_fmmu = has_unknown_fmmu || fmmu_sm_role(fmmu.type) == SmRole::unknown;
        if (has_unknown_fmmu) continue;
        for (std::size_t n = 0; n < device->sms.size(); ++n) {
            const SyncManager& sm = device->sms[n];
            if (sm.is_virtual && *sm.is_virtual) continue;
            const SmRole role = device_sm_role(*device, sm);
            const bool outputs = role == SmRole::outputs;
            if ((!outputs && role != SmRole::inputs) || !carries_data(*device, n)) continue;
            if (outputs ? has_outputs_fmmu : has_inputs_fmmu) continue;
            const std::string kind = outputs ? "Outputs" : "Inputs";
            context.report(sm.pos, "SM" + std::to_string(n) + " '" + sm.type + "' carries process data but the device has no " +
                                       kind + " Fmmu; without it the master has no FMMU to map the " +
                                       (outputs ? "outputs" : "inputs") + " into the process image");
            if (outputs) has_outputs_fmmu = true;  // one finding per direction
            else has_inputs_fmmu = true;
        }
    }
}

constexpr Rule fmmu_missing{
    .id = "fmmu-missing",
    .default_severity = Severity::warning,
    .summary = "Process data without an FMMU of that direction",
    .rationale =
        "Process data reaches the master's logical image only through an FMMU; the schema leaves Fmmu optional, so a "
        "generator that forgets it produces a schema-valid file whose device never exchanges process data (ETG.2000 "
        "DeviceType: Fmmu minOccurs 0; the SII FMMU category of ETG.2010 is built from these elements, and "
        "ethercrab-rs/ethercrab #287 shows a master guessing FMMUs for an EEPROM that lists too few; CTT TF-1300 3-3 "
        "counts them). The rule fires once per direction for the first SM that carries data (a DefaultSize or default "
        "PDOs) without an FMMU of its kind.",
    .bad_example =
        "<Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" DefaultSize=\"1\" Enable=\"1\">Outputs</Sm> (no Fmmu)",
    .good_example =
        "<Fmmu>Outputs</Fmmu> ... <Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" DefaultSize=\"1\" "
        "Enable=\"1\">Outputs</Sm>",
    .check = check_missing,
};

// ---- fmmu-count -------------------------------------------------------------------------------

void check_fmmu_count(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document))
        report_blocks_past_limit(*device, device->fmmus, "FmmuCount", "FMMUs", "FMMU", context);
}

constexpr Rule fmmu_count{
    .id = "fmmu-count",
    .default_severity = Severity::error,
    .summary = "More Fmmu elements than the ESC has FMMUs (EtherCATController/FmmuCount, at most 16)",
    .rationale =
        "The master configures one FMMU per Fmmu element in the register block 0x0600 + 16n (ETG.1000.4; ESC "
        "datasheet section II). An ESC has as many FMMUs as its register 0x0004 says (2 to 16), stated in the ESI as "
        "Info/EtherCATController/FmmuCount, and the register map has room for 16 at most. The SII FMMU category "
        "(ETG.2010) lists the same elements and the conformance tool counts them (CTT TF-1300 3-3); an FMMU the ESC "
        "lacks maps nothing, so the direction it was meant for exchanges no process data. A vendor's own, lower "
        "limit is profile-fmmu-count's (limits.max_fmmus).",
    .bad_example = "<Info><EtherCATController><FmmuCount>2</FmmuCount></EtherCATController></Info> … <Fmmu>Outputs</Fmmu>"
                   "<Fmmu>Inputs</Fmmu><Fmmu>MBoxState</Fmmu>",
    .good_example = "<Info><EtherCATController><FmmuCount>3</FmmuCount></EtherCATController></Info> … <Fmmu>Outputs</Fmmu>"
                    "<Fmmu>Inputs</Fmmu><Fmmu>MBoxState</Fmmu>",
    .check = check_fmmu_count,
};

}  // namespace

void add_fmmu(std::vector<Rule>& out) {
    out.insert(out.end(), {
        fmmu_type_unknown,
        fmmu_sm_reference,
        fmmu_missing,
        fmmu_count,
    });
}

}  // namespace esi::rules
