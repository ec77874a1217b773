// Rules of the pdo area on the PDO list of a device or module: index ranges, SyncManager
// references, duplicates, Exclude references and the 8-bit limits of the CoE mapping and assignment
// objects.
#include <algorithm>
#include <vector>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "check/od_text.hpp"
#include "check/pdo_scope.hpp"
#include "check/queries.hpp"
#include "check/slot_places.hpp"
#include "check/source_edit.hpp"
#include "esi/model/limits.hpp"

namespace esi::rules {

namespace {

// ETG.1000.6 object dictionary areas: RxPdo mapping 0x1600-0x17FF, TxPdo mapping 0x1A00-0x1BFF.
constexpr IndexRange rx_mapping_area{0x1600, 0x17FF};
constexpr IndexRange tx_mapping_area{0x1A00, 0x1BFF};

std::string range_text(const IndexRange& range) { return object_address(range.first) + "-" + object_address(range.last); }

std::string pdo_name(const Pdo& pdo) { return std::string(pdo.element_name()) + " " + object_address(pdo.index); }

// A PDO whose Index is missing or unreadable was reported by the reader; its index means nothing.
bool has_index(const Pdo& pdo) { return pdo.index_pos.line != 0 && !pdo.index_invalid; }

SourcePos index_or_element(const Pdo& pdo) { return pdo.index_pos.line != 0 ? pdo.index_pos : pdo.pos; }

std::string sm_list(const Device& device) {
    if (device.sms.empty()) return "declares no Sm";
    if (device.sms.size() == 1) return "declares only SM0";
    return "declares SM0-SM" + std::to_string(device.sms.size() - 1);
}

// ---- pdo-index-range, pdo-index-area -------------------------------------------------------

// Whether the master writes a device's PDO indices: into the assignment objects 0x1C12/0x1C13
// (CoE PdoAssign) or as the mapping object it downloads (CoE PdoConfig).
bool master_writes_pdo_indices(const Device& device) {
    if (!device.mailbox || !device.mailbox->coe) return false;
    const CoeProtocol& coe = *device.mailbox->coe;
    return coe.pdo_assign.value_or(false) || coe.pdo_config.value_or(false);
}

// A PDO whose index, in some slot, lies outside its direction's mapping area.
struct OutOfArea {
    const Pdo& pdo;
    std::uint32_t index;          // the index there (the base index outside a slot)
    std::optional<std::uint32_t> slot;  // the slot number, for slot-dependent indices
    bool written;                 // the master writes this index (PdoAssign/PdoConfig)
};

// Calls f(OutOfArea) once per PDO whose index is outside its mapping area in any slot it can
// take, for devices with CoE and for modules. A slot-dependent index is judged where the module
// sits (ETG.2000 DependOnSlot), not by its base; a module the document plugs into no device is
// judged by its base index, and then nothing says whether a master writes it.
template <class F>
void for_each_out_of_area(const EsiDocument& document, RuleContext& context, F&& f) {
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        // The ranges are those of CoE mapping objects. Devices without CoE (simple terminals,
        // SoE drives whose MDT/AT carry IDNs) number their PDOs freely in the SII.
        if (scope.device && !(scope.device->mailbox && scope.device->mailbox->coe)) continue;
        const std::vector<SlotPlace> places = scope.module ? slot_places(document, *scope.module) : std::vector<SlotPlace>{};
        const bool written = scope.device ? master_writes_pdo_indices(*scope.device)
                                          : std::any_of(places.begin(), places.end(),
                                                        [](const SlotPlace& p) { return master_writes_pdo_indices(*p.device); });
        scope.for_each_pdo([&](const Pdo& pdo) {
            if (!has_index(pdo)) return;
            const IndexRange& area = pdo.direction == PdoDirection::rx ? rx_mapping_area : tx_mapping_area;
            if (places.empty() || !depends_on_slot(pdo)) {
                if (!area.contains(pdo.index)) f(OutOfArea{pdo, pdo.index, std::nullopt, written});
                return;
            }
            for (const auto& place : places) {
                const std::uint32_t index = pdo_index_in(pdo, place);
                if (area.contains(index)) continue;
                f(OutOfArea{pdo, index, place.slot_number, master_writes_pdo_indices(*place.device)});
                return;  // one finding per PDO
            }
        });
    }
}

std::string out_of_area_message(const OutOfArea& o) {
    const Pdo& pdo = o.pdo;
    const bool rx = pdo.direction == PdoDirection::rx;
    const IndexRange& area = rx ? rx_mapping_area : tx_mapping_area;
    std::string message = std::string(pdo.element_name()) + " index " + object_address(o.index);
    if (o.slot) message += " (" + object_address(pdo.index) + " in slot " + std::to_string(*o.slot) + ")";
    message += " is outside the " + std::string(pdo.element_name()) + " mapping area " + range_text(area);
    const IndexRange& other = rx ? tx_mapping_area : rx_mapping_area;
    if (other.contains(o.index))
        message += "; " + object_address(o.index) + (rx ? " is a TxPdo" : " is an RxPdo") + " index, so the PDO is probably declared with the wrong element";
    return message;
}

void check_index_range(const EsiDocument& document, RuleContext& context) {
    for_each_out_of_area(document, context, [&](const OutOfArea& o) {
        if (o.written) context.report(o.pdo.index_pos, out_of_area_message(o));
    });
}

constexpr Rule pdo_index_range{
    .id = "pdo-index-range",
    .default_severity = Severity::error,
    .summary = "RxPdo index outside 0x1600-0x17FF or TxPdo index outside 0x1A00-0x1BFF, where the master writes it",
    .rationale =
        "The PDO index is the index of its mapping object, and ETG.1000.6 reserves 0x1600-0x17FF for RxPDO mapping "
        "and 0x1A00-0x1BFF for TxPDO mapping. A master that assigns or configures PDOs (CoE PdoAssign or PdoConfig) "
        "writes exactly that index into 0x1C12/0x1C13 and downloads the mapping into that object; a slave stack that "
        "checks the range aborts the SDO and the transition to SafeOp fails, one that does not takes a TxPDO mapping "
        "object for outputs. The SOES tutorial and the item C series and Afag SE-Power EtherCAT manuals (§6.1.1, "
        "Tabelle 5: RxPDOs 0x1600-0x1603, TxPDOs 0x1A00-0x1A03) rely on the split. An index in the other range "
        "usually means the PDO was declared with the wrong element. A slot-dependent index (DependOnSlot, "
        "DependOnSlotGroup) is judged in every slot the module can take (ETG.2000 Slots: SlotPdoIncrement). Where "
        "CoE declares neither PdoAssign nor PdoConfig the index is only a label (pdo-index-area); devices without CoE "
        "have no mapping objects at all and are not checked.",
    .bad_example =
        "<TxPdo Sm=\"3\"><Index>#x1600</Index><Name>Inputs</Name>…</TxPdo> … <CoE PdoAssign=\"true\" PdoConfig=\"true\"/>",
    .good_example =
        "<TxPdo Sm=\"3\"><Index>#x1A00</Index><Name>Inputs</Name>…</TxPdo> … <CoE PdoAssign=\"true\" PdoConfig=\"true\"/>",
    .check = check_index_range,
};

void check_index_area(const EsiDocument& document, RuleContext& context) {
    for_each_out_of_area(document, context, [&](const OutOfArea& o) {
        if (!o.written)
            context.report(o.pdo.index_pos, out_of_area_message(o) + "; the index is a label only, as CoE declares neither "
                                                                     "PdoAssign nor PdoConfig");
    });
}

constexpr Rule pdo_index_area{
    .id = "pdo-index-area",
    .default_severity = Severity::warning,
    .summary = "A PDO index outside its mapping area on a device whose CoE neither assigns nor configures PDOs",
    .rationale =
        "ETG.1000.6 reserves 0x1600-0x17FF for RxPDO and 0x1A00-0x1BFF for TxPDO mapping objects. When the device's "
        "CoE element declares neither PdoAssign nor PdoConfig (ETG.2000 CoE attributes), a master never writes the "
        "index into 0x1C12/0x1C13 nor downloads a mapping into it: the index only names the PDO in the SII PDO "
        "category and in configuration tools, and the process image does not depend on it. Still, the index "
        "contradicts the device's mapping objects, which CoE masters may read, and usually means the PDO was "
        "declared with the wrong element (Beckhoff EL9800 evaluation board: RxPdo 0x1A00, TxPdo 0x1600). A module "
        "that no device of the file takes is judged here too, since nothing says whether its PDOs are written.",
    .bad_example = "<RxPdo Sm=\"2\"><Index>#x1A00</Index>…</RxPdo> … <CoE/>",
    .good_example = "<RxPdo Sm=\"2\"><Index>#x1600</Index>…</RxPdo> … <CoE/>",
    .check = check_index_area,
};

// ---- pdo-sm-unknown -------------------------------------------------------------------------

void check_sm_unknown(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        if (!scope.device) continue;  // a module's Sm refers to the SMs of the device it is plugged into
        const Device& device = *scope.device;
        scope.for_each_pdo([&](const Pdo& pdo) {
            if (!pdo.sm || *pdo.sm < device.sms.size()) return;
            context.report(pdo.pos, pdo_name(pdo) + " is assigned to SM" + std::to_string(*pdo.sm) + " (Sm=\"" +
                                        std::to_string(*pdo.sm) + "\"), but the device " + sm_list(device));
        });
    }
}

constexpr Rule pdo_sm_unknown{
    .id = "pdo-sm-unknown",
    .default_severity = Severity::error,
    .summary = "A PDO is assigned (Sm=) to a SyncManager the device does not declare",
    .rationale =
        "Sm=\"n\" assigns the PDO by default to SyncManager n of the device's Sm list (ETG.2000 PdoType@Sm). When SM "
        "n does not exist the master has nowhere to put the process data: the SII PDO category points at a missing SM "
        "and TwinCAT refuses the configuration (ETG.2010 PDO category 'SyncM').",
    .bad_example = "<Sm …>MBoxOut</Sm><Sm …>MBoxIn</Sm><Sm …>Outputs</Sm><RxPdo Sm=\"4\">…",
    .good_example = "<Sm …>MBoxOut</Sm><Sm …>MBoxIn</Sm><Sm …>Outputs</Sm><RxPdo Sm=\"2\">…",
    .check = check_sm_unknown,
};

// ---- pdo-sm-direction -----------------------------------------------------------------------

void check_sm_direction(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        if (!scope.device) continue;
        const Device& device = *scope.device;
        scope.for_each_pdo([&](const Pdo& pdo) {
            if (!pdo.sm || *pdo.sm >= device.sms.size()) return;
            const SyncManager& sm = device.sms[*pdo.sm];
            const bool rx = pdo.direction == PdoDirection::rx;
            const SmRole expected = rx ? SmRole::outputs : SmRole::inputs;
            SmRole role = role_from_text(sm.type);
            if (role == SmRole::unknown) {
                if (!sm.control_byte) return;
                // Without a type text the ControlByte decides. Devices without a mailbox run
                // process data through one-buffer SMs (#x44/#x46) that look like mailbox SMs by
                // their mode bits, so there only the direction counts.
                role = device.mailbox ? sm_role(sm)
                                      : (control_byte_is_write(*sm.control_byte) ? SmRole::outputs : SmRole::inputs);
            }
            if (role == expected) return;
            // MBoxOut, MBoxIn, Outputs and Inputs all take "an".
            std::string message = pdo_name(pdo) + " is assigned to SM" + std::to_string(*pdo.sm) + ", which is an " +
                                  std::string(to_string(role)) + " SyncManager; " +
                                  (rx ? "RxPdos carry outputs (master to slave) and belong to an Outputs SM"
                                      : "TxPdos carry inputs (slave to master) and belong to an Inputs SM");
            context.report(pdo.pos, std::move(message), {context.note(sm.pos, "SM" + std::to_string(*pdo.sm) + " is declared here")});
        });
    }
}

constexpr Rule pdo_sm_direction{
    .id = "pdo-sm-direction",
    .default_severity = Severity::error,
    .summary = "An RxPdo on an input SM or a TxPdo on an output SM",
    .rationale =
        "RxPDOs carry outputs (master to slave) and must sit in an Outputs SyncManager (ControlByte direction "
        "'write', usually SM2, #x24/#x64); TxPDOs carry inputs and belong to an Inputs SM (usually SM3, #x20). The "
        "item C series and Afag SE-Power EtherCAT manuals fix SM2 for RxPDOs and SM3 for TxPDOs (§6.1.1, Tabelle 13), "
        "and their §6.7.3 says a TxPDO is configured like the RxPDO apart from its Name, which, taken literally, "
        "keeps Sm=\"2\". Process data on the wrong SM are never exchanged (SOES tutorial SM table; "
        "OpenEtherCATsociety/SOEM #247).",
    .bad_example = "<TxPdo Sm=\"2\"><Index>#x1A00</Index>…",
    .good_example = "<TxPdo Sm=\"3\"><Index>#x1A00</Index>…",
    .check = check_sm_direction,
};

// ---- pdo-duplicate-index, pdo-duplicate-label ----------------------------------------------

// Whether two PDOs of one index name one CoE mapping object: both exist in the device (not
// Virtual, which TwinCAT maps from ESC registers) and the owner has CoE, where the index is the
// mapping object's and 0x1C12/0x1C13 assign PDOs by it. A module's PDOs are CoE mapping objects.
bool index_names_one_mapping_object(const PdoScope& scope, const Pdo& a, const Pdo& b) {
    if (a.is_virtual.value_or(false) || b.is_virtual.value_or(false)) return false;
    return !scope.device || (scope.device->mailbox && scope.device->mailbox->coe);
}

// Calls f(scope, pdo, first) for every PDO whose index an earlier PDO of its owner already uses,
// in the order of the PDOs.
template <class F>
void for_each_repeated_index(const EsiDocument& document, RuleContext& context, F&& f) {
    // The indexed PDOs of an owner sorted by index and, among equal indices, by their order: a
    // repeat follows the first of its index. Owners have a handful of PDOs and repeats are rare,
    // so sorting one reused array costs less than a map per owner.
    struct Indexed {
        std::uint32_t index;
        std::size_t order;  // in PdoScope::for_each_pdo
        const Pdo* pdo;
    };
    struct Repeat {
        std::size_t order;
        const Pdo* pdo;
        const Pdo* first;
    };
    std::vector<Indexed> by_index;
    std::vector<Repeat> repeats;
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        by_index.clear();
        std::size_t order = 0;
        scope.for_each_pdo([&](const Pdo& pdo) {
            if (has_index(pdo)) by_index.push_back(Indexed{pdo.index, order, &pdo});
            ++order;
        });
        std::sort(by_index.begin(), by_index.end(),
                  [](const Indexed& a, const Indexed& b) { return a.index < b.index || (a.index == b.index && a.order < b.order); });
        repeats.clear();
        std::size_t first = 0;  // of the run of equal indices
        for (std::size_t i = 1; i < by_index.size(); ++i) {
            if (by_index[i].index != by_index[first].index) first = i;
            else repeats.push_back(Repeat{by_index[i].order, by_index[i].pdo, by_index[first].pdo});
        }
        std::sort(repeats.begin(), repeats.end(), [](const Repeat& a, const Repeat& b) { return a.order < b.order; });
        for (const Repeat& r : repeats) f(scope, *r.pdo, *r.first);
    }
}

void report_repeated_index(RuleContext& context, const PdoScope& scope, const Pdo& pdo, const Pdo& first, std::string_view consequence) {
    // A byte-identical copy of the first PDO (a paste made twice) goes without losing anything.
    context.report(pdo.index_pos,
                   std::string(pdo.element_name()) + " index " + object_address(pdo.index) + " is already used by " +
                       (first.direction == pdo.direction ? "another " : "a ") + std::string(first.element_name()) +
                       (scope.device ? " of this device" : " of this module") + std::string(consequence),
                   {context.note(index_or_element(first), "first declared here")},
                   remove_identical_copy(context.document(), first.pos, pdo.pos, "remove the identical copy of the PDO"));
}

void check_duplicate_index(const EsiDocument& document, RuleContext& context) {
    for_each_repeated_index(document, context, [&](const PdoScope& scope, const Pdo& pdo, const Pdo& first) {
        if (index_names_one_mapping_object(scope, pdo, first)) report_repeated_index(context, scope, pdo, first, "");
    });
}

constexpr Rule pdo_duplicate_index{
    .id = "pdo-duplicate-index",
    .default_severity = Severity::error,
    .summary = "Two PDOs of one CoE device or module share an index",
    .rationale =
        "A PDO index names one mapping object; two PDOs with the same index cannot both be assigned, and a master keeps "
        "only one of them (KickCAT warns on duplicate PDO indices; ETG.1000.6 one object per index). RxPdo and TxPdo "
        "share the index space. Where no index is written to the device (no CoE, or a Virtual PDO that TwinCAT maps "
        "from ESC registers), the repeat is pdo-duplicate-label's warning.",
    .bad_example = "<RxPdo><Index>#x1600</Index>…</RxPdo><RxPdo><Index>#x1600</Index>…</RxPdo> … <CoE/>",
    .good_example = "<RxPdo><Index>#x1600</Index>…</RxPdo><RxPdo><Index>#x1601</Index>…</RxPdo> … <CoE/>",
    .check = check_duplicate_index,
    .fix = "removes the second PDO when it is a byte-identical copy of the first",
};

void check_duplicate_label(const EsiDocument& document, RuleContext& context) {
    for_each_repeated_index(document, context, [&](const PdoScope& scope, const Pdo& pdo, const Pdo& first) {
        if (!index_names_one_mapping_object(scope, pdo, first))
            report_repeated_index(context, scope, pdo, first, "; no index is written to the device, but Exclude and OpMode "
                                                              "references to it are ambiguous");
    });
}

constexpr Rule pdo_duplicate_label{
    .id = "pdo-duplicate-label",
    .default_severity = Severity::warning,
    .summary = "Two PDOs share an index where the index is only a label (no CoE, or a Virtual PDO)",
    .rationale =
        "A device without CoE has no mapping objects, and a Virtual PDO (ETG.2000 PdoType@Virtual) is mapped by TwinCAT "
        "from ESC registers rather than assigned: no master writes these indices to the device, and the process "
        "image follows the PDOs' SM assignment and entries (Beckhoff EL2252: a virtual RxPdo 0x1602 'DC Sync "
        "Activate' beside an empty mandatory RxPdo 0x1602 'Reserved'). The index still names the PDO in the SII PDO "
        "category, in Exclude lists and in Dc/OpMode Sm/Pdo references, which become ambiguous: a warning. Where CoE "
        "assigns PDOs by index, it is pdo-duplicate-index's error.",
    .bad_example = "<RxPdo Virtual=\"true\"><Index>#x1602</Index>…</RxPdo><RxPdo><Index>#x1602</Index>…</RxPdo>",
    .good_example = "<RxPdo Virtual=\"true\"><Index>#x1602</Index>…</RxPdo><RxPdo><Index>#x1604</Index>…</RxPdo>",
    .check = check_duplicate_label,
    .fix = "removes the second PDO when it is a byte-identical copy of the first",
};

// ---- pdo-exclude-unknown --------------------------------------------------------------------

void check_exclude_unknown(const EsiDocument& document, RuleContext& context) {
    std::vector<std::uint32_t> indices;  // of the PDOs of one owner
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        // Drives list every other PDO as excluded (Beckhoff AX2xxx): look indices up in a sorted list.
        indices.clear();
        scope.for_each_pdo([&](const Pdo& pdo) { indices.push_back(pdo.index); });
        std::sort(indices.begin(), indices.end());
        scope.for_each_pdo([&](const Pdo& pdo) {
            for (const auto& exclude : pdo.excludes) {
                if (exclude.depend_on_slot.value_or(false) || exclude.depend_on_slot_group.value_or(false)) continue;
                if (std::binary_search(indices.begin(), indices.end(), exclude.index)) continue;
                context.report(exclude.pos, pdo_name(pdo) + " excludes " + object_address(exclude.index) + ", which is not a PDO of this " +
                                                (scope.device ? "device" : "module"));
            }
        });
    }
}

constexpr Rule pdo_exclude_unknown{
    .id = "pdo-exclude-unknown",
    .default_severity = Severity::warning,
    .summary = "Exclude names a PDO that does not exist",
    .rationale =
        "Exclude lists the PDOs that cannot be assigned together with this one (ETG.2000 PdoType/Exclude); configuration "
        "tools grey them out. An Exclude that names no PDO of the device is a typo or a leftover from a removed PDO, and "
        "the exclusion it was meant to express is lost. Slot-dependent excludes (DependOnSlot) are not checked.",
    .bad_example = "<RxPdo><Index>#x1600</Index><Exclude>#x1610</Exclude>…</RxPdo> (no PDO #x1610)",
    .good_example =
        "<RxPdo><Index>#x1600</Index><Exclude>#x1601</Exclude>…</RxPdo><RxPdo><Index>#x1601</Index>…</RxPdo>",
    .check = check_exclude_unknown,
};

// ---- pdo-legacy-ref -------------------------------------------------------------------------

// A PDO of the form before ETG.2000: no Index and no entries, only Ref="name" of a description kept
// elsewhere (<RxPdo Ref="AX2000Out" Fixed="1" Sm="0"/>).
const XmlAttribute* legacy_ref(const Pdo& pdo) {
    if (pdo.index_pos.line != 0 || !pdo.entries.empty()) return nullptr;
    return pdo.extras.attribute("Ref");
}

void check_legacy_ref(const EsiDocument& document, RuleContext& context) {
    const Pdo* first = nullptr;
    std::size_t count = 0;
    for (const auto& scope : context.cache().pdo_scopes(document))
        scope.for_each_pdo([&](const Pdo& pdo) {
            if (!legacy_ref(pdo)) return;
            if (!first) first = &pdo;
            ++count;
        });
    if (!first) return;
    // One finding per file: the form is the file's, not one PDO's fault.
    std::string message = std::string(first->element_name()) + " Ref=\"" + legacy_ref(*first)->value +
                          "\" describes its layout by a pre-ETG.2000 reference";
    if (count > 1) message += ", and so do " + std::to_string(count - 1) + " more PDO" + (count > 2 ? "s" : "") + " of this file";
    message += "; no tool has the referenced descriptions, so the process image cannot be taken from this file";
    context.report(first->pos, std::move(message));
}

constexpr Rule pdo_legacy_ref{
    .id = "pdo-legacy-ref",
    .default_severity = Severity::error,
    .summary = "PDOs given by a pre-ETG.2000 Ref= instead of Index and entries (once per file)",
    .rationale =
        "Since ETG.2000 a PDO carries its Index and its entries (ETG.2000 PdoType: Index is required). Files from "
        "before it name a PDO description kept elsewhere instead (<RxPdo Ref=\"AX2000Out\" Fixed=\"1\" Sm=\"0\"/>, "
        "Beckhoff's EtherCAT_Terminals catalogue); those descriptions are in no file a tool has, so neither a master "
        "nor the SII builder can take the process image from the description, and the schema rejects the PDO. An "
        "error, reported once per file with the number of such PDOs rather than once per PDO, since the form is the "
        "file's.",
    .bad_example = "<RxPdo Ref=\"AX2000Out\" Fixed=\"1\" Mandatory=\"1\" Sm=\"0\"/>",
    .good_example = "<RxPdo Fixed=\"1\" Mandatory=\"1\" Sm=\"0\"><Index>#x1600</Index><Name>Outputs</Name><Entry>…</Entry></RxPdo>",
    .check = check_legacy_ref,
};

// ---- pdo-mapping-limits ---------------------------------------------------------------------

void check_mapping_limits(const EsiDocument& document, RuleContext& context) {
    // ETG.1000.6: a mapping object (0x16xx/0x1Axx) and an assignment object (0x1C1x) count their
    // sub-entries in the 8-bit sub-index 0, and a mapping entry keeps the length in 8 bits.
    constexpr std::size_t max_subentries = 255;
    constexpr std::uint32_t max_bit_len = 255;
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        for (const auto* list : {scope.rx_pdos, scope.tx_pdos}) {
            if (list->size() > max_subentries) {
                const Pdo& first_excess = (*list)[max_subentries];
                context.report(first_excess.pos, "this is " + std::string(first_excess.element_name()) + " number " +
                                                     std::to_string(max_subentries + 1) + " of " + std::to_string(list->size()) +
                                                     "; a PDO assignment object lists at most 255 PDOs");
            }
            for (const auto& pdo : *list) {
                if (pdo.entries.size() > max_subentries)
                    context.report(pdo.pos, pdo_name(pdo) + " has " + std::to_string(pdo.entries.size()) +
                                                " entries; a PDO mapping object holds at most 255");
                for (const auto& entry : pdo.entries) {
                    // BitLen 0 maps nothing. On a padding entry it leaves the image as it is
                    // (pdo-padding-bitlen-zero); on an object it is a corrupt mapping entry.
                    if (entry.bit_len == 0 && !entry.is_padding() && entry.bit_len_pos.line) {
                        context.report(entry.bit_len_pos, entry_label(entry) +
                                                              " has BitLen 0; a mapping entry maps 1 to 255 bits of its object, "
                                                              "so this one maps nothing");
                        continue;
                    }
                    if (entry.bit_len <= max_bit_len) continue;
                    context.report(entry.bit_len_pos.line ? entry.bit_len_pos : entry.pos,
                                   entry_label(entry) + " has BitLen " +
                                       std::to_string(entry.bit_len) + "; a PDO mapping entry stores the length in 8 bits (at most 255)");
                }
            }
        }
    }
}

constexpr Rule pdo_mapping_limits{
    .id = "pdo-mapping-limits",
    .default_severity = Severity::error,
    .summary = "More than 255 entries in a PDO, BitLen 0 or above 255, or more than 255 PDOs",
    .rationale =
        "The CoE mapping objects count their entries in the 8-bit sub-index 0 and store each entry's length in 8 "
        "bits; the assignment objects 0x1C1x likewise list at most 255 PDOs (ETG.1000.6 PDO mapping/assignment; the "
        "SII PDO category of ETG.2010 has one-byte counts too). leducp/KickCAT rejects such files ('>255 entries', "
        "'BitLen > 255'). A BitLen of 0 on an object maps nothing; a padding entry with BitLen 0 leaves the process "
        "image as it is and is pdo-padding-bitlen-zero's warning.",
    .bad_example = "<Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>512</BitLen>…</Entry>",
    .good_example = "<Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>32</BitLen>…</Entry>",
    .check = check_mapping_limits,
};

}  // namespace

void add_pdo_structure(std::vector<Rule>& out) {
    out.insert(out.end(), {
        pdo_index_range,
        pdo_index_area,
        pdo_sm_unknown,
        pdo_sm_direction,
        pdo_duplicate_index,
        pdo_duplicate_label,
        pdo_legacy_ref,
        pdo_exclude_unknown,
        pdo_mapping_limits,
    });
}

}  // namespace esi::rules
