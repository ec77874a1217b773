// Rules of the pdo area that check PDO entries against the objects they map: the object and
// sub-index exist, BitLen and DataType (including signedness) agree with the object, and the object
// may be mapped in that direction.
#include <algorithm>

#include "check/areas.hpp"
#include "check/od_text.hpp"
#include "check/pdo_entry_type.hpp"
#include "check/pdo_scope.hpp"
#include "check/queries.hpp"
#include "check/rule_cache.hpp"

namespace esi::rules {

namespace {

// Entries whose object can be looked up: not padding, a readable index that does not depend on
// the slot a module sits in.
bool addresses_an_object(const PdoEntry& entry) {
    return !entry.is_padding() && !entry.index_invalid && !depends_on_slot(entry);
}

// Oversampling PDOs (OSFac/OSIndexInc) are repeated with shifted entry indices, so their entries
// do not name the objects the Dictionary describes one to one.
bool is_oversampling(const Pdo& pdo) { return pdo.os_fac || pdo.os_index_inc; }

// Objects that ETG profiles define and that masters know without the ESI describing them:
// SM communication/diagnosis objects 0x10F0-0x10FF (e.g. 0x10F4 external synchronisation status),
// TxPDO communication parameters 0x1800-0x19FF (sub-index 7 TxPDO state, 9 TxPDO toggle;
// ETG.1000.6) and the modular device profile area 0xF000-0xFFFF (ETG.5001). Beckhoff maps them
// routinely while its ESI Dictionaries leave them out.
bool is_profile_infrastructure(std::uint32_t index) {
    return (index >= 0x10F0 && index <= 0x10FF) || (index >= 0x1800 && index <= 0x19FF) || index >= 0xF000;
}

// A PDO entry that names an object, with the owner's Dictionary and types at hand.
struct MappedEntry {
    const PdoScope& scope;
    const DictionaryIndex& dictionary;
    const TypeIndex& types;
    PdoEntryFacts& facts;
    std::size_t position;  // of the entry in `facts`
    const Pdo& pdo;
    const PdoEntry& entry;

    // The object the entry maps; nullptr when the Dictionary has none of its index.
    [[nodiscard]] const Object* object() const { return facts.object(position); }
    // The object sub-entry the entry maps; nullptr when the object or sub-index is missing.
    [[nodiscard]] const ObjectEntry* target() const { return facts.target(position); }
    // What the entry's DataType means.
    [[nodiscard]] const EntryType& type() const { return facts.type(position); }
};

template <class F>
void for_each_mapped_entry(const EsiDocument& document, RuleContext& context, bool complete_dictionaries_only, F&& f) {
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        if (!scope.dictionary || scope.dictionary->objects.empty()) continue;
        if (complete_dictionaries_only && !scope.dictionary_is_complete) continue;
        const DictionaryIndex& dictionary = context.cache().objects(scope.dictionary);
        const TypeIndex& types = context.cache().types(scope.dictionary);
        PdoEntryFacts& entries = context.cache().pdo_entries(scope);
        for (std::size_t i = 0; i < entries.size(); ++i) {
            const Pdo& pdo = entries.pdo(i);
            const PdoEntry& entry = entries.entry(i);
            if (!is_oversampling(pdo) && addresses_an_object(entry)) f(MappedEntry{scope, dictionary, types, entries, i, pdo, entry});
        }
    }
}

std::string object_label(const Object& object) {
    std::string out = "object " + object_address(object.index);
    if (const std::string& name = primary_text(object.names); !name.empty()) out += " '" + name + "'";
    return out;
}

std::string subindex_list(const ObjectLayout& layout) {
    if (layout.entries.empty()) return "no sub-entries";
    std::uint32_t low = layout.entries.front().subindex;
    std::uint32_t high = low;
    for (const auto& e : layout.entries) {
        low = std::min(low, e.subindex);
        high = std::max(high, e.subindex);
    }
    if (low == high) return "only subindex " + std::to_string(low);
    return "subindices " + std::to_string(low) + "-" + std::to_string(high);
}

SourcePos index_or_entry(const PdoEntry& entry) { return entry.index_pos.line ? entry.index_pos : entry.pos; }

// "object #x6064 'Position actual value'" for a VAR, "object entry #x6000:02 'Underrange'" for a
// sub-entry of a record or array.
std::string target_label(const Object& object, const ObjectEntry& target) {
    if (!target.type_item && target.subindex == 0) return object_label(object);
    std::string out = "object entry " + entry_address(object.index, target.subindex);
    if (!target.name.empty()) out += " '" + target.name + "'";
    return out;
}

// ---- pdo-entry-object-missing ---------------------------------------------------------------

void check_entry_object_missing(const EsiDocument& document, RuleContext& context) {
    for_each_mapped_entry(document, context, true, [&](const MappedEntry& m) {
        const PdoEntry& entry = m.entry;
        if (is_profile_infrastructure(entry.index)) return;
        const Object* object = m.object();
        if (!object) {
            context.report(index_or_entry(entry), entry_label(entry) + " maps object " + object_address(entry.index) +
                                                      ", which the device's Dictionary does not contain");
            return;
        }
        if (m.target()) return;
        const ObjectLayout& layout = m.dictionary.layout(*object);
        // An object whose type does not resolve has no known sub-entries (od-type-unresolved says why).
        const DataType* type = m.types.find(object->type);
        if (m.types.status(object->type) != TypeNameStatus::resolved || (type && type->base_type && m.types.in_base_type_cycle(*type)))
            return;
        context.report(index_or_entry(entry), entry_label(entry) + " maps subindex " + std::to_string(entry.effective_subindex()) +
                                                  " of " + object_label(*object) + ", which has " + subindex_list(layout),
                       {context.note(object->pos, "the object is declared here")});
    });
}

constexpr Rule pdo_entry_object_missing{
    .id = "pdo-entry-object-missing",
    .default_severity = Severity::warning,
    .summary = "A PDO entry maps an object or sub-index the Dictionary does not contain",
    .rationale =
        "A PDO entry maps Dictionary object Index:SubIndex. When the device ships its Dictionary in the ESI, a mapped "
        "object that is not in it cannot be configured over SDO: the device answers abort 0x06020000 'object does not "
        "exist' (OpenEtherCATsociety/SOEM #402) or 0x06040041 'cannot be mapped' (STÖBER ECS 5000 EtherCAT manual "
        "§7.2.3). Checked only for devices whose own Dictionary lists objects; modules, modular devices and "
        "slot-dependent indices (DependOnSlot) take objects from elsewhere, oversampling PDOs shift their indices, "
        "and objects that ETG profiles define (0x10F0-0x10FF, TxPDO parameters 0x1800-0x19FF, the modular device area "
        "0xF000-0xFFFF) are known to masters without the ESI (ETG.1000.6 communication area; ETG.5001 modular device "
        "profile).",
    .bad_example = "<Entry><Index>#x6064</Index>…</Entry> with no Object #x6064",
    .good_example = "<Object><Index>#x6064</Index>…</Object> … <Entry><Index>#x6064</Index>…</Entry>",
    .check = check_entry_object_missing,
};

// ---- pdo-entry-object-type ------------------------------------------------------------------

void check_entry_object_type(const EsiDocument& document, RuleContext& context) {
    for_each_mapped_entry(document, context, false, [&](const MappedEntry& m) {
        const PdoEntry& entry = m.entry;
        const ObjectEntry* target = m.target();
        if (!target || !target->basic) return;
        const EntryType& type = m.type();
        if (!type.known || !type.basic) return;
        // A size difference is pdo-entry-object-bitlen's finding, which names both types.
        if (target->bit_size != 0 && entry.bit_len != target->bit_size) return;
        const ValueKind written = value_kind(*type.basic);
        const ValueKind actual = value_kind(*target->basic);
        if (written == actual || written == ValueKind::other || actual == ValueKind::other) return;
        const Object* object = m.object();
        context.report(entry.data_type_pos.line ? entry.data_type_pos : entry.pos,
                       entry_label(entry) + " has DataType " + *entry.data_type + " (" + std::string(to_string(written)) + ") but " +
                           target_label(*object, *target) + " is " + target->type + " (" + std::string(to_string(actual)) +
                           "); one of the two is stale, and masters type the process variable by the entry",
                       {context.note(object->pos, "the object is declared here")});
    });
}

constexpr Rule pdo_entry_object_type{
    .id = "pdo-entry-object-type",
    .default_severity = Severity::warning,
    .summary = "A PDO entry's DataType differs in kind (signedness) from the object it maps",
    .rationale =
        "The entry's DataType is what masters use to type the process variable; the object's type is what the "
        "offline Dictionary says the firmware puts there. Where they differ in kind, one of them is stale: a signed "
        "value typed UDINT reads -1 as 4294967295, a REAL typed DINT is garbage. Generators that choose the "
        "DataType by bit width alone produce this (leducp/KickCAT test mapping_target_subindex_reconciled_against_object "
        "reconciles an entry with its object), but so does a Dictionary left behind when the firmware changed the "
        "value (Beckhoff EL3692 maps 0x6002:01 as REAL while its Dictionary still says DINT). The sizes agree (a size "
        "difference is pdo-entry-object-bitlen's finding), so the process-image layout is right and the device "
        "reaches OP; only the type of one variable is in doubt, and the rule cannot tell which side is wrong: a "
        "warning that names both. Types of the same kind and width (UINT/WORD, BOOL/BIT1) are accepted.",
    .bad_example =
        "<Object><Index>#x6064</Index><Type>DINT</Type>… <Entry><Index>#x6064</Index><BitLen>32</BitLen><DataType>UDINT</DataType>",
    .good_example =
        "<Object><Index>#x6064</Index><Type>DINT</Type>… <Entry><Index>#x6064</Index><BitLen>32</BitLen><DataType>DINT</DataType>",
    .check = check_entry_object_type,
};

// ---- pdo-entry-object-bitlen, pdo-entry-narrower-than-object ------------------------------

// How an entry's BitLen relates to the size of the object it maps.
enum class BitLenFit {
    agrees,                 // equal, or nothing to compare
    bool_as_bit,            // a BOOL object stored in a byte, mapped as the one bit it means
    narrower_alternative,   // a compact variant: an excluded PDO maps the object at full width
    narrower_fixed,         // narrower in a fixed PDO: the device's own mapping, the Dictionary disagrees
    narrower,               // narrower in a PDO the master may configure
    wider,                  // wider than the object
};

// Whether `pdo` excludes a PDO of the same owner and direction that maps the same object entry
// with `bits`. Beckhoff offers process data as a full-width PDO and a "compact" one that maps
// the same objects narrower, each excluding the other (ETG.2000 PdoType/Exclude): only one of
// them is ever assigned.
bool has_full_width_alternative(const PdoScope& scope, const Pdo& pdo, const PdoEntry& entry, std::uint64_t bits) {
    const std::vector<Pdo>& same_direction = pdo.direction == PdoDirection::rx ? *scope.rx_pdos : *scope.tx_pdos;
    for (const auto& exclude : pdo.excludes)
        for (const auto& other : same_direction) {
            if (&other == &pdo || other.index != exclude.index) continue;
            for (const auto& e : other.entries)
                if (e.index == entry.index && e.effective_subindex() == entry.effective_subindex() && e.bit_len == bits) return true;
        }
    return false;
}

BitLenFit bitlen_fit(const MappedEntry& m, const ObjectEntry*& target) {
    const PdoEntry& entry = m.entry;
    target = nullptr;
    if (entry.bit_len == 0 || entry.bit_len_pos.line == 0) return BitLenFit::agrees;
    target = m.target();
    if (!target || target->bit_size == 0 || target->bit_size == entry.bit_len) return BitLenFit::agrees;
    // When BitLen already disagrees with the entry's own DataType, pdo-entry-bitlen-type reports it.
    const EntryType& type = m.type();
    if (type.known && type.bit_size != 0 && type.bit_size != entry.bit_len) return BitLenFit::agrees;
    if (entry.bit_len > target->bit_size) return BitLenFit::wider;
    if (entry.bit_len == 1 && target->bit_size == 8 && target->basic && target->basic->esi_name == "BOOL") return BitLenFit::bool_as_bit;
    if (has_full_width_alternative(m.scope, m.pdo, entry, target->bit_size)) return BitLenFit::narrower_alternative;
    return m.pdo.fixed.value_or(false) ? BitLenFit::narrower_fixed : BitLenFit::narrower;
}

void report_bitlen(RuleContext& context, const MappedEntry& m, const ObjectEntry& target, std::string_view consequence) {
    const PdoEntry& entry = m.entry;
    const Object* object = m.object();
    std::string written = entry.data_type && !entry.data_type->empty() ? " (" + *entry.data_type + ")" : "";
    context.report(entry.bit_len_pos, entry_label(entry) + " has BitLen " + std::to_string(entry.bit_len) + written + " but " +
                                          target_label(*object, target) + " is " + target.type + ", " + bits_text(target.bit_size) +
                                          std::string(consequence),
                   {context.note(object->pos, "the object is declared here")});
}

void check_entry_object_bitlen(const EsiDocument& document, RuleContext& context) {
    for_each_mapped_entry(document, context, false, [&](const MappedEntry& m) {
        const ObjectEntry* target = nullptr;
        const BitLenFit fit = bitlen_fit(m, target);
        if (fit == BitLenFit::wider || fit == BitLenFit::narrower) report_bitlen(context, m, *target, "");
    });
}

constexpr Rule pdo_entry_object_bitlen{
    .id = "pdo-entry-object-bitlen",
    .default_severity = Severity::error,
    .summary = "A PDO entry's BitLen is larger than the object it maps, or smaller in a PDO the master configures",
    .rationale =
        "The device fills the process image with the object's own size; an ESI entry with another BitLen makes the "
        "master read a different layout than the slave writes (STÖBER ECS 5000 EtherCAT manual §7.1.1: the device "
        "reports the mapped length; SDO abort 0x06040042 'length exceeds PDO'). A BitLen larger than the object is "
        "always reported. A smaller one is reported where the PDO is not Fixed, so the master downloads this mapping "
        "and the device may refuse a length below its object's (ETG.1000.6 PDO mapping); not reported are compact "
        "variants (the PDO excludes another that maps the same object at full width, ETG.2000 PdoType/Exclude), BOOL "
        "objects stored in a byte and mapped as one bit, and narrower entries of Fixed PDOs "
        "(pdo-entry-narrower-than-object). Reported only when BitLen agrees with the entry's own DataType (otherwise "
        "pdo-entry-bitlen-type reports it).",
    .bad_example =
        "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>16</BitSize>… <RxPdo><Entry><Index>#x6041</Index><BitLen>32</BitLen>",
    .good_example =
        "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>16</BitSize>… <RxPdo><Entry><Index>#x6041</Index><BitLen>16</BitLen>",
    .check = check_entry_object_bitlen,
};

void check_entry_narrower_than_object(const EsiDocument& document, RuleContext& context) {
    for_each_mapped_entry(document, context, false, [&](const MappedEntry& m) {
        const ObjectEntry* target = nullptr;
        if (bitlen_fit(m, target) == BitLenFit::narrower_fixed)
            report_bitlen(context, m, *target, "; the PDO is Fixed, so the process image has the entry's BitLen and the "
                                               "offline Dictionary disagrees with it");
    });
}

constexpr Rule pdo_entry_narrower_than_object{
    .id = "pdo-entry-narrower-than-object",
    .default_severity = Severity::warning,
    .summary = "A Fixed PDO maps an object with a BitLen smaller than the object's size",
    .rationale =
        "A Fixed PDO's mapping is the device's own and is never downloaded (ETG.2000 PdoType/Fixed), so masters lay "
        "out the process image from the entries' BitLen, which is what the device sends; only the offline Dictionary "
        "(ETG.2000 ObjectType/BitSize) disagrees, and a tool that sizes the variable from the object, or reads it by "
        "SDO, sees more bits than the process image holds (Beckhoff EL6690: 0xF100:01 UDINT mapped as 24 bits). "
        "Inconsistent but tolerated by masters: a warning. Where the master configures the mapping, "
        "pdo-entry-object-bitlen reports it as an error.",
    .bad_example =
        "<Object><Index>#xF100</Index>…<SubItem><Name>CycleTimer</Name><Type>UDINT</Type><BitSize>32</BitSize>… "
        "<TxPdo Fixed=\"1\"><Entry><Index>#xF100</Index><SubIndex>1</SubIndex><BitLen>24</BitLen>",
    .good_example =
        "<TxPdo Fixed=\"1\"><Entry><Index>#xF100</Index><SubIndex>1</SubIndex><BitLen>32</BitLen>",
    .check = check_entry_narrower_than_object,
};

// ---- pdo-entry-not-mappable -----------------------------------------------------------------

void check_entry_not_mappable(const EsiDocument& document, RuleContext& context) {
    for_each_mapped_entry(document, context, false, [&](const MappedEntry& m) {
        const Pdo& pdo = m.pdo;
        const PdoEntry& entry = m.entry;
        const ObjectEntry* target = m.target();
        if (!target) return;
        const Object* object = m.object();
        // The sub-item's own flags win; a record's object-level flags cover sub-items without.
        const std::string* mapping = nullptr;
        if (target->flags && target->flags->pdo_mapping) mapping = &*target->flags->pdo_mapping;
        else if (object->flags && object->flags->pdo_mapping) mapping = &*object->flags->pdo_mapping;
        // Without any PdoMapping flag the ESI says nothing about mappability: generators such as
        // SOES's and Beckhoff's own communication objects (0x1C32:20, 0x1800:09) omit it, and
        // devices map them all the same.
        if (!mapping) return;
        const bool rx = pdo.direction == PdoDirection::rx;
        const char wanted = rx ? 'r' : 't';
        const std::string& flag = *mapping;
        for (char c : flag)
            if ((c | 0x20) == wanted) return;
        std::string message = entry_label(entry) + " is mapped into " + std::string(pdo.element_name()) + " " +
                              object_address(pdo.index) + " but " + target_label(*object, *target) + " has PdoMapping '" + flag +
                              "'; " + (rx ? "an RxPdo needs R" : "a TxPdo needs T");
        context.report(index_or_entry(entry), std::move(message), {context.note(object->pos, "the object is declared here")});
    });
}

constexpr Rule pdo_entry_not_mappable{
    .id = "pdo-entry-not-mappable",
    .default_severity = Severity::warning,
    .summary = "A PDO entry maps an object whose PdoMapping flag forbids that direction",
    .rationale =
        "Objects declare whether they may be mapped into RxPDOs (R), TxPDOs (T) or both (Flags/PdoMapping, ETG.2000 "
        "ObjectType; lower case marks optional mapping). A device rejects a mapping of any other object with SDO "
        "abort 0x06040041 'object cannot be mapped into the PDO' (STÖBER ECS 5000 EtherCAT manual §7.1.1, §7.2.3: "
        "only parameters marked 'PDO' can be mapped); the SSC spreadsheet's rx/tx column has the same meaning (ET9300 "
        "§13). Objects without any PdoMapping flag are not reported: many generators omit the flag altogether.",
    .bad_example =
        "<Object><Index>#x6041</Index>…<Flags><PdoMapping>T</PdoMapping></Flags></Object> mapped into an RxPdo",
    .good_example =
        "<Object><Index>#x6040</Index>…<Flags><PdoMapping>R</PdoMapping></Flags></Object> mapped into an RxPdo",
    .check = check_entry_not_mappable,
};

}  // namespace

void add_pdo_object(std::vector<Rule>& out) {
    out.insert(out.end(), {
        pdo_entry_object_missing,
        pdo_entry_object_type,
        pdo_entry_object_bitlen,
        pdo_entry_narrower_than_object,
        pdo_entry_not_mappable,
    });
}

}  // namespace esi::rules
