// Rules of the od area on the DataTypes of a Dictionary and on the type names its objects use
// (ETG.2000 DictionaryType; XSD keys DataTypeKey/BaseTypeRef/SubItemTypeRef/ObjectTypesRef).
#include <algorithm>
#include <map>
#include <string>
#include <unordered_set>
#include <vector>

#include "check/areas.hpp"
#include "check/od_layout_faults.hpp"
#include "check/od_scope.hpp"
#include "check/od_type_sizes.hpp"
#include "check/od_text.hpp"
#include "check/od_type_index.hpp"
#include "check/od_type_references.hpp"
#include "check/rule_cache.hpp"
#include "check/source_edit.hpp"
#include "esi/data_types.hpp"
#include "esi/number.hpp"

namespace esi::rules {

namespace {

std::string describe(const TypeReference& ref) {
    if (ref.object) return "Object " + object_address(ref.object->index);
    if (ref.sub_item) return "SubItem '" + ref.sub_item->name + "' of DataType " + ref.data_type->name;
    return "DataType " + ref.data_type->name + " (BaseType)";
}

// Reports one finding per distinct name: the first reference, with how many others there are.
struct NameFindings {
    struct Entry {
        TypeReference first;
        std::string culprit;
        std::size_t count = 0;
    };
    std::vector<Entry> entries;
    std::map<std::string, std::size_t, std::less<>> by_name;

    void add(const TypeReference& ref, std::string_view culprit) {
        const auto it = by_name.find(culprit);
        if (it != by_name.end()) {
            ++entries[it->second].count;
            return;
        }
        by_name.emplace(std::string(culprit), entries.size());
        entries.push_back(Entry{ref, std::string(culprit), 1});
    }
};

std::string also_used(std::size_t count) {
    if (count <= 1) return "";
    return " (used " + std::to_string(count) + " times; first here)";
}

// ---- od-type-unresolved ---------------------------------------------------------------------

void check_type_unresolved(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        NameFindings findings;
        for (const auto& ref : context.cache().referenced_types(*scope.dictionary))
            if (ref.status == TypeNameStatus::unresolved) findings.add(ref.reference, ref.culprit);
        for (const auto& f : findings.entries) {
            std::string message = describe(f.first) + " uses type '" + std::string(f.first.name) + "', ";
            message += f.culprit != f.first.name ? "whose element type '" + f.culprit + "'" : std::string("which");
            message += " is neither a basic ESI type nor a DataType of this Dictionary" + also_used(f.count);
            context.report(f.first.pos, std::move(message));
        }
    }
}

constexpr Rule od_type_unresolved{
    .id = "od-type-unresolved",
    .default_severity = Severity::error,
    .summary = "An Object, SubItem or BaseType names a type that is not defined",
    .rationale =
        "Every Object/Type, SubItem/Type and BaseType must name a basic ESI type or a DataType of the same Dictionary; the "
        "ETG schema states this as the keyrefs ObjectTypesRef, SubItemTypeRef and BaseTypeRef (ETG.2000 EtherCATBase.xsd). "
        "A type that does not resolve has no size and no sub-entries, so masters cannot read the object and generators "
        "cannot lay it out (KickCAT: 'unresolved Type reference'). Reported once per missing name.",
    .bad_example = "<Object><Index>#x6000</Index><Type>DT6000</Type>…</Object> with no DataType DT6000",
    .good_example =
        "<DataType><Name>DT6000</Name>…</DataType> … <Object><Index>#x6000</Index><Type>DT6000</Type>…</Object>",
    .check = check_type_unresolved,
};

// ---- od-nonstandard-type-name ---------------------------------------------------------------

void check_nonstandard_type_name(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        // A Dictionary may define a DataType of any name, INT8 included (Beckhoff's SoE
        // dictionaries do); only names nothing defines are faults.
        NameFindings findings;
        for (const auto& ref : context.cache().referenced_types(*scope.dictionary))
            if (ref.status == TypeNameStatus::nonstandard) findings.add(ref.reference, ref.culprit);
        for (const auto& f : findings.entries)
            context.report(f.first.pos, describe(f.first) + " uses type '" + f.culprit + "', which is not an ESI type name; the standard name is '" +
                                            std::string(standard_type_name_for(f.culprit)) + "'" + also_used(f.count));
    }
}

constexpr Rule od_nonstandard_type_name{
    .id = "od-nonstandard-type-name",
    .default_severity = Severity::warning,
    .summary = "A type named with a non-standard spelling (UINT16 instead of UINT)",
    .rationale =
        "ESI type names are the IEC 61131-3 style names of ETG.2000 and ET9300 Table 22 (USINT, UINT, UDINT, SINT, "
        "INT, DINT, BOOL, REAL, …). C-style and TwinCAT spellings such as UINT8/UINT16/UINT32 or CoE names such as "
        "UNSIGNED16 name the same types (generators such as pollen-robotics/pyesi emit them), so the object's size "
        "and layout are known; tools that only know the standard names lose the offline type. A vendor spelling in "
        "the offline Dictionary: a warning that names the standard spelling, like pdo-entry-type-spelling for PDO "
        "entries. A Dictionary may define a DataType of such a name; only names that nothing defines are reported.",
    .bad_example = "<Object><Index>#x6041</Index><Type>UINT16</Type><BitSize>16</BitSize></Object>",
    .good_example = "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>16</BitSize></Object>",
    .check = check_nonstandard_type_name,
};

// ---- od-type-cycle --------------------------------------------------------------------------

void check_type_cycle(const EsiDocument& document, RuleContext& context) {
    const auto before = [](const SourcePos& a, const SourcePos& b) { return a.line < b.line || (a.line == b.line && a.column < b.column); };
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        const TypeIndex& types = context.cache().types(scope.dictionary);
        std::unordered_set<const DataType*> seen;
        for (const auto& type : scope.dictionary->data_types) {
            if (!types.is_first_of_name(type) || !types.in_base_type_cycle(type) || seen.count(&type)) continue;
            // One finding per loop, at the member that comes first in the file; the loop is
            // walked once.
            std::vector<const DataType*> members;
            const DataType* first = &type;
            for (const DataType* t = &type; t && seen.insert(t).second; t = types.find(*t->base_type)) {
                members.push_back(t);
                if (before(t->pos, first->pos)) first = t;
            }
            // Name the loop starting at its first member.
            const auto at = std::find(members.begin(), members.end(), first);
            std::rotate(members.begin(), at, members.end());
            std::string chain;
            for (const DataType* m : members) chain += m->name + " -> ";
            chain += first->name;
            context.report(first->name_pos.line ? first->name_pos : first->pos,
                           "DataType " + first->name + " is its own base type through BaseType: " + chain);
        }
    }
}

constexpr Rule od_type_cycle{
    .id = "od-type-cycle",
    .default_severity = Severity::error,
    .summary = "DataTypes whose BaseType chain loops",
    .rationale =
        "A DataType refers to its base through BaseType; a chain that comes back to where it started has no base at "
        "all, and a naive resolver recurses forever (KickCAT test throws_on_basetype_cycle limits the depth for this "
        "reason).",
    .bad_example =
        "<DataType><Name>DT_A</Name><BaseType>DT_B</BaseType>…</DataType><DataType><Name>DT_B</Name><BaseType>DT_A</BaseType>…",
    .good_example = "<DataType><Name>DT_A</Name><BaseType>UINT</BaseType><BitSize>16</BitSize></DataType>",
    .check = check_type_cycle,
};

// ---- od-subitem-layout, od-layout-complete-access -----------------------------------------

void check_subitem_layout(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        for (const auto& type : scope.dictionary->data_types) {
            const LayoutFaults faults = layout_faults(type);
            // Past the end: reported once per DataType, at the first such SubItem in the file.
            if (const DataTypeSubItem* item = faults.past_end)
                context.report(item->pos, "SubItem '" + item->name + "' ends at bit " + std::to_string(item->bit_offset + item->bit_size) +
                                              " but DataType " + type.name + " has BitSize " + std::to_string(type.bit_size));
            if (!faults.overlapping) continue;
            // One finding per DataType: a type whose BitOffs were never filled in overlaps everywhere.
            const auto bits = [](const DataTypeSubItem& i) {
                return std::to_string(i.bit_offset) + "-" + std::to_string(i.bit_offset + i.bit_size - 1);
            };
            std::string message = "SubItem '" + faults.overlapping->name + "' (bits " + bits(*faults.overlapping) + ") overlaps SubItem '" +
                                  faults.overlapped->name + "' (bits " + bits(*faults.overlapped) + ") in DataType " + type.name;
            if (faults.overlap_count > 1) message += " (" + std::to_string(faults.overlap_count) + " SubItems overlap others)";
            context.report(faults.overlapping->pos, std::move(message), {context.note(faults.overlapped->pos, "the other SubItem")});
        }
    }
}

constexpr Rule od_subitem_layout{
    .id = "od-subitem-layout",
    .default_severity = Severity::warning,
    .summary = "DataType SubItems that overlap or extend past the DataType's BitSize",
    .rationale =
        "The SubItems of a record type are laid out by BitOffs and BitSize inside the type's BitSize (ETG.2000 "
        "DataTypeType). Overlapping SubItems make two sub-entries share bits, and a SubItem past the end reads beyond "
        "the object; generated structs and offline tools then disagree with the device. Bit offsets matter only to "
        "complete access, which transfers a record packed by its layout (ETG.1000.6 SDO complete access); masters "
        "read and write sub-indices one at a time otherwise, and the process image is laid out by PDO entries, not "
        "by this layout. Real catalogues carry such offline layouts (BitOffs all 0, a typo in one offset, a struct "
        "BitSize left smaller than every user of the type declares), so this is a warning; where an InitCmd writes "
        "such a type by complete access, od-layout-complete-access reports an error. Overlaps are checked between "
        "sub-indices (SubItems with SubIdx) only, since SoE dictionaries describe unions with overlapping structure "
        "members; one finding per DataType and kind.",
    .bad_example =
        "<DataType><Name>DT2000</Name><BitSize>32</BitSize><SubItem><Name>A</Name><Type>UINT</Type><BitSize>16</BitSize>"
        "<BitOffs>16</BitOffs></SubItem><SubItem><Name>B</Name><Type>UINT</Type><BitSize>16</BitSize><BitOffs>24</BitOffs>…",
    .good_example =
        "<DataType><Name>DT2000</Name><BitSize>48</BitSize><SubItem><Name>A</Name><Type>UINT</Type><BitSize>16</BitSize>"
        "<BitOffs>16</BitOffs></SubItem><SubItem><Name>B</Name><Type>UINT</Type><BitSize>16</BitSize><BitOffs>32</BitOffs>…",
    .check = check_subitem_layout,
};

void check_layout_complete_access(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos)
        for (const auto& device : info.devices) {
            const Dictionary* dictionary = device.dictionary();
            if (!dictionary || !device.mailbox || !device.mailbox->coe) continue;
            const TypeIndex& types = context.cache().types(dictionary);
            const DictionaryIndex& objects = context.cache().objects(dictionary);
            for (const auto& cmd : device.mailbox->coe->init_cmds) {
                if (!cmd.complete_access.value_or(false) || !cmd.index) continue;
                const Object* object = objects.object(*cmd.index);
                if (!object) continue;
                const DataType* type = types.find(trim(object->type));
                if (!type) continue;
                const LayoutFaults faults = layout_faults(*type);
                if (!faults.any()) continue;
                const DataTypeSubItem& item = faults.past_end ? *faults.past_end : *faults.overlapping;
                context.report(cmd.pos,
                               "CoE InitCmd writes " + object_address(*cmd.index) + " by complete access, but DataType " + type->name +
                                   " of that object " +
                                   (faults.past_end ? "has a SubItem past its BitSize" : std::string("has overlapping sub-indices")) +
                                   "; the bytes transferred are packed by a layout the description gets wrong",
                               {context.note(item.pos, "the faulty SubItem")});
            }
        }
}

constexpr Rule od_layout_complete_access{
    .id = "od-layout-complete-access",
    .default_severity = Severity::error,
    .summary = "A CoE InitCmd writes by complete access an object whose DataType layout is faulty",
    .rationale =
        "An SDO download with complete access transfers all sub-indices of a record at once, packed by the record's "
        "layout (ETG.1000.6 SDO complete access; ETG.2000 InitCmd@CompleteAccess). Configuration tools compose and show "
        "such a start-up command by the DataType's BitOffs and BitSize; when SubItems overlap or one lies past the "
        "type's BitSize, the data the master downloads do not match the object the device has, and the device "
        "aborts the SDO (0x06070010 'length of service parameter does not match') or stores values in the wrong "
        "sub-indices. The same faulty layout without a complete-access write is od-subitem-layout's warning.",
    .bad_example =
        "<DataType><Name>DT8000</Name><BitSize>32</BitSize><SubItem><SubIdx>1</SubIdx>…<BitSize>16</BitSize><BitOffs>16</BitOffs>"
        "</SubItem><SubItem><SubIdx>2</SubIdx>…<BitSize>16</BitSize><BitOffs>16</BitOffs>… <InitCmd CompleteAccess=\"1\">"
        "<Index>#x8000</Index>",
    .good_example =
        "<DataType><Name>DT8000</Name><BitSize>48</BitSize><SubItem><SubIdx>1</SubIdx>…<BitSize>16</BitSize><BitOffs>16</BitOffs>"
        "</SubItem><SubItem><SubIdx>2</SubIdx>…<BitSize>16</BitSize><BitOffs>32</BitOffs>… <InitCmd CompleteAccess=\"1\">"
        "<Index>#x8000</Index>",
    .check = check_layout_complete_access,
};

// ---- od-array-size --------------------------------------------------------------------------

void check_array_size(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        const DataTypeSizes& sizes = context.cache().type_sizes(*scope.dictionary);
        for (const auto& type : scope.dictionary->data_types) {
            const ArraySize& size = sizes.array(type);
            if (size.fit == ArrayFit::negative) {
                context.report(size.negative->pos, "ArrayInfo of DataType " + type.name + " has Elements " +
                                                       std::to_string(size.negative->elements) + "; the element count cannot be negative");
                continue;
            }
            if (size.fit != ArrayFit::mismatch) continue;
            context.report(type.array_info.front().pos,
                           "DataType " + type.name + " has " + std::to_string(size.elements) + " elements of " +
                               std::string(trim(*type.base_type)) + " (" + bits_text(size.element_bits) + " each, " +
                               bits_text(size.elements * size.element_bits) + ") but BitSize " + std::to_string(type.bit_size));
        }
    }
}

constexpr Rule od_array_size{
    .id = "od-array-size",
    .default_severity = Severity::warning,
    .summary = "An array DataType whose ArrayInfo disagrees with its BitSize",
    .rationale =
        "An array type's BitSize is the number of elements (ArrayInfo/Elements) times the size of its BaseType "
        "(ETG.2000 ArrayInfo). When they disagree, the number of sub-indices or their offsets in the offline "
        "Dictionary is wrong; KickCAT rejects such types ('array BitSize not divisible by elements', test "
        "throws_on_array_bitsize_not_divisible_by_elements). A type is judged with its users: an SoE list's element "
        "array may have the size of the whole list record, 32 bits more for the current and maximum length words "
        "(the list format of IEC 61800-7-204 that SoE carries; Beckhoff AX5 dictionaries), when every user is the "
        "Elements SubItem of such a record and declares the elements alone; arrays of BOOL/BITn may be rounded up to "
        "whole bytes; Elements 0 with BitSize 0 (an empty PDO assignment list) is consistent. Masters read and write "
        "array sub-indices one at a time and lay out process data by PDO entries, so an inconsistent offline array "
        "is a warning.",
    .bad_example =
        "<DataType><Name>DT1C12ARR</Name><BaseType>UINT</BaseType><BitSize>48</BitSize><ArrayInfo><LBound>1</LBound>"
        "<Elements>2</Elements></ArrayInfo></DataType>",
    .good_example =
        "<DataType><Name>DT1C12ARR</Name><BaseType>UINT</BaseType><BitSize>32</BitSize><ArrayInfo><LBound>1</LBound>"
        "<Elements>2</Elements></ArrayInfo></DataType>",
    .check = check_array_size,
};

// ---- od-bitsize -----------------------------------------------------------------------------

void check_bitsize(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        const TypeIndex& types = context.cache().types(scope.dictionary);
        const DataTypeSizes& sizes = context.cache().type_sizes(*scope.dictionary);
        // A user's size that differs from a DataType whose own BitSize is the cause (an array
        // od-array-size reports, a struct od-subitem-layout finds too small) or is a convention
        // (SoE list, whole bytes) is not reported again: one finding per cause.
        const auto type_accounts_for_users = [&](std::string_view name) {
            const DataType* t = types.find(trim(name));
            return t && sizes.own_size_accounts_for_users(*t);
        };
        // The references come DataType by DataType (its BaseType, then its SubItems), then the
        // Objects: a finding about a DataType's own name precedes those about its SubItems.
        const std::vector<ReferencedType>& refs = context.cache().referenced_types(*scope.dictionary);
        std::size_t r = 0;
        for (const auto& type : scope.dictionary->data_types) {
            // A DataType named like a basic, STRING(n) or array type must have the size the name implies.
            if (type.bit_size > 0 && types.is_first_of_name(type)) {
                if (const std::optional<std::uint64_t> implied = implied_bit_size(type.name); implied && *implied != type.bit_size)
                    context.report(type.name_pos.line ? type.name_pos : type.pos, "DataType " + type.name + " has BitSize " +
                                                                                      std::to_string(type.bit_size) + " but " + type.name +
                                                                                      " is " + bits_text(*implied));
            }
            for (; r < refs.size() && refs[r].reference.data_type == &type; ++r) {
                const ReferencedType& ref = refs[r];
                const DataTypeSubItem* item = ref.reference.sub_item;
                if (!item || item->bit_size == 0) continue;  // the BaseType, or a SubItem without BitSize
                const std::optional<std::uint64_t>& bits = ref.bit_size;
                if (!bits || *bits == item->bit_size || type_accounts_for_users(ref.reference.name)) continue;
                context.report(item->pos, "SubItem '" + item->name + "' of DataType " + type.name + " has BitSize " +
                                              std::to_string(item->bit_size) + " but its type " + std::string(ref.reference.name) + " is " +
                                              bits_text(*bits));
            }
        }
        for (; r < refs.size(); ++r) {
            const ReferencedType& ref = refs[r];
            const Object& object = *ref.reference.object;
            if (object.bit_size == 0 || object.bit_size_pos.line == 0) continue;
            const std::optional<std::uint64_t>& bits = ref.bit_size;
            if (!bits || *bits == object.bit_size || type_accounts_for_users(ref.reference.name)) continue;
            context.report(object.bit_size_pos, "Object " + object_address(object.index) + " has BitSize " + std::to_string(object.bit_size) +
                                                    " but its type " + std::string(ref.reference.name) + " is " + bits_text(*bits));
        }
    }
}

constexpr Rule od_bitsize{
    .id = "od-bitsize",
    .default_severity = Severity::warning,
    .summary = "An Object's or SubItem's BitSize disagrees with its type",
    .rationale =
        "BitSize states the size of the object or sub-item; the type states it too (UINT is 16 bits, STRING(10) 80, a "
        "DataType its own BitSize; ET9300 Table 22, ETG.2000 ObjectType/BitSize). When they differ, SDO uploads, "
        "complete access and generated object tables disagree about the object's length. A DataType named like a "
        "basic type (Beckhoff lists <DataType><Name>UINT</Name><BitSize>16</BitSize>) must have that size. Where the "
        "DataType's own BitSize is the cause (an array od-array-size reports, a structure whose SubItems run past its "
        "BitSize, which od-subitem-layout reports) or a convention explains it (an SoE list's element array, BOOL "
        "arrays in whole bytes), its users are not reported again.",
    .bad_example = "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>32</BitSize></Object>",
    .good_example = "<Object><Index>#x6041</Index><Type>UINT</Type><BitSize>16</BitSize></Object>",
    .check = check_bitsize,
};

// ---- od-duplicate-datatype ------------------------------------------------------------------

void check_duplicate_datatype(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        const TypeIndex& types = context.cache().types(scope.dictionary);
        for (const auto& type : scope.dictionary->data_types) {
            if (types.is_first_of_name(type)) continue;
            const DataType* first = types.find(type.name);
            if (!first) continue;
            context.report(type.name_pos.line ? type.name_pos : type.pos,
                           "DataType " + type.name + " is defined twice in this Dictionary; masters use one of the definitions",
                           {context.note(first->name_pos.line ? first->name_pos : first->pos, "first defined here")},
                           remove_identical_copy(document, first->pos, type.pos, "remove the identical copy of the DataType"));
        }
    }
}

constexpr Rule od_duplicate_datatype{
    .id = "od-duplicate-datatype",
    .default_severity = Severity::error,
    .summary = "Two DataTypes of one Dictionary share a name",
    .rationale =
        "DataType names are the keys objects use to refer to types; the ETG schema requires them to be unique "
        "(EtherCATBase.xsd key DataTypeKey). With two definitions, tools pick either one and may lay the object out "
        "differently.",
    .bad_example =
        "<DataType><Name>DT6000</Name><BitSize>24</BitSize>…</DataType><DataType><Name>DT6000</Name><BitSize>48</BitSize>…",
    .good_example =
        "<DataType><Name>DT6000</Name><BitSize>24</BitSize>…</DataType><DataType><Name>DT6010</Name><BitSize>48</BitSize>…",
    .check = check_duplicate_datatype,
    .fix = "removes the second DataType when it is a byte-identical copy of the first",
};

}  // namespace

void add_od_type(std::vector<Rule>& out) {
    out.insert(out.end(), {
        od_type_unresolved,
        od_nonstandard_type_name,
        od_type_cycle,
        od_subitem_layout,
        od_layout_complete_access,
        od_array_size,
        od_bitsize,
        od_duplicate_datatype,
    });
}

}  // namespace esi::rules
