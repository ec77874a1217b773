// Rules of the od area on the objects of a Dictionary: presence of the mandatory objects,
// duplicates, flag values, and default/minimum/maximum values against the entry they belong to.
#include <algorithm>
#include <string>

#include "check/areas.hpp"
#include "check/od_scope.hpp"
#include "check/od_text.hpp"
#include "check/od_type_index.hpp"
#include "check/od_values.hpp"
#include "check/rule_cache.hpp"
#include "check/source_edit.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::rules {

namespace {

struct MandatoryObject {
    std::uint32_t index;
    std::string_view name;
};
// ETG.1000.6 / CiA 301: every CoE device has Device type (0x1000) and Identity (0x1018); CTT
// TF-2301 tests both.
constexpr MandatoryObject mandatory_objects[] = {{0x1000, "Device type"}, {0x1018, "Identity"}};

std::string number_text(const Number& n) { return format_decimal(n); }

// The flags a Dictionary declares: objects' and DataType SubItems'.
template <class F>
void for_each_flags(const Dictionary& dictionary, F&& f) {
    for (const auto& type : dictionary.data_types)
        for (const auto& item : type.sub_items)
            if (item.flags) f(*item.flags);
    for (const auto& object : dictionary.objects)
        if (object.flags) f(*object.flags);
}

// The values ETG.2000 ObjectType/Flags allows. Compared with literals, which the compiler turns
// into a length test and one load: every object and SubItem of a Dictionary has flags.
bool is_access(std::string_view value) { return value == "ro" || value == "rw" || value == "wo"; }
bool is_pdo_mapping(std::string_view value) {
    return value == "R" || value == "T" || value == "RT" || value == "TR" || value == "r" || value == "t" || value == "rt" || value == "tr";
}
bool is_category(std::string_view value) { return value == "m" || value == "o" || value == "c"; }

// A value of an entry, where its default, minimum and maximum come from.
struct EntryValues {
    const RareOptional<Number>& default_value;
    const std::optional<HexData>& default_data;
    const RareOptional<Number>& min_value;
    const RareOptional<HexData>& min_data;
    const RareOptional<Number>& max_value;
    const RareOptional<HexData>& max_data;
    const RareOptional<std::string>& default_string;
};

EntryValues values_of(const ObjectInfo& info) {
    return {info.default_value, info.default_data, info.min_value, info.min_data, info.max_value, info.max_data, info.default_string};
}

const RareOptional<HexData> no_data;

EntryValues values_of(const DataTypeSubItem& item) {
    return {item.default_value, item.default_data, item.min_value, no_data, item.max_value, no_data, item.default_string};
}

// What a message calls the entry, built only when there is something to report.
struct EntryName {
    const Object* object = nullptr;  // object entries
    std::uint32_t subindex = 0;
    bool whole_object = false;  // a VAR: the object itself
    const DataType* type = nullptr;  // DataType SubItems
    const DataTypeSubItem* item = nullptr;

    [[nodiscard]] std::string text() const {
        if (item) return "SubItem '" + item->name + "' of DataType " + type->name;
        return whole_object ? object_address(object->index) : entry_address(object->index, subindex);
    }
};

// The length check of one DefaultData/MinData/MaxData whose byte count differs from the size of
// the entry (`bits`): strings and byte arrays may be given shorter than their maximum length, and
// data that is not hex gives no value at all.
void judge_data_length(RuleContext& context, const HexData& data, std::string_view element, const EntryName& name,
                       std::string_view type_name, const BasicType* basic, std::uint64_t bits, SourcePos fallback) {
    const std::uint64_t bytes = (bits + 7) / 8;
    const std::uint64_t length = data.byte_length();
    // (Only a name starting with ARRAY can parse as an array; the test spares a parse.)
    const bool variable = !basic || basic->type_class == TypeClass::visible_string || basic->type_class == TypeClass::octet_string ||
                          basic->type_class == TypeClass::unicode_string ||
                          (trim(type_name).starts_with("ARRAY") && parse_type_name(type_name).kind == TypeName::Kind::array);
    if ((variable && length <= bytes) || !data.valid()) return;
    context.report(data.pos.line ? data.pos : fallback,
                   std::string(element) + " of " + name.text() + " is " + std::to_string(length) + (length == 1 ? " byte" : " bytes") +
                       " but the entry (" + std::string(type_name) + ", " + bits_text(bits) + ") is " + (variable ? "at most " : "") +
                       std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes"));
}

// Whether an entry has values whose length is judged: data or a DefaultString.
bool has_lengths(const EntryValues& values) { return values.default_data || values.min_data || values.max_data || values.default_string; }

// Length checks of DefaultData/MinData/MaxData and DefaultString for an entry of `bits` bits.
void check_lengths(RuleContext& context, const EntryValues& values, const EntryName& name, std::string_view type_name,
                   const BasicType* basic, std::uint64_t bits, SourcePos fallback) {
    if (bits == 0) return;
    const std::uint64_t bytes = (bits + 7) / 8;
    const auto check = [&](const std::optional<HexData>& data, std::string_view element) {
        // Empty data (<DefaultData/>) gives no value at all. Nearly every value has the entry's
        // length, which is all this tests; the rest is judge_data_length's.
        if (!data || data->text.empty() || data->byte_length() == bytes) return;
        judge_data_length(context, *data, element, name, type_name, basic, bits, fallback);
    };
    check(values.default_data, "DefaultData");
    check(values.min_data, "MinData");
    check(values.max_data, "MaxData");
    if (values.default_string && values.default_string->size() > bytes)
        context.report(fallback, "DefaultString of " + name.text() + " has " + std::to_string(values.default_string->size()) +
                                     " bytes but the entry (" + std::string(type_name) + ") holds " + std::to_string(bytes));
}

struct Reading {
    std::optional<Number> default_value;
    std::optional<Number> min;
    std::optional<Number> max;
};

// The entry's values as numbers. With `as_bit_patterns`, HexDecValues that only fit the entry's
// width as two's complement are read that way (#xfff80001 for a DINT, -1 for a UDINT). Data of
// the wrong length is left out: od-default-length reports it, and its value is a guess.
Reading read_values(const EntryValues& values, const ValueFormat& format, bool as_bit_patterns) {
    const std::uint64_t bytes = (format.bit_size + 7) / 8;
    const auto pick = [&](const std::optional<Number>& value, const std::optional<HexData>& data) -> std::optional<Number> {
        if (value) return as_bit_patterns ? normalized(*value, format) : *value;
        // number_from_data reads nothing from data that is not hex.
        if (data && data->byte_length() == bytes) return number_from_data(*data, format);
        return std::nullopt;
    };
    Reading r{pick(values.default_value, values.default_data), pick(values.min_value, values.min_data),
              pick(values.max_value, values.max_data)};
    // MinValue 0 with MaxValue 0 is how generated dictionaries say "no limits" (Beckhoff's SoE
    // dictionaries: default 5000 with both limits 0).
    if (r.min && r.max && r.min->magnitude == 0 && r.max->magnitude == 0) r.min = r.max = std::nullopt;
    return r;
}

std::optional<std::string> range_violation(const Reading& r, const ValueFormat& format, const EntryName& name,
                                           std::string_view type_name) {
    if (r.min && r.max && less(*r.max, *r.min))
        return "MinValue " + number_text(*r.min) + " of " + name.text() + " is greater than its MaxValue " + number_text(*r.max);
    if (!r.default_value) return std::nullopt;
    const Number& def = *r.default_value;
    if (r.min && less(def, *r.min)) return "the default " + number_text(def) + " of " + name.text() + " is below its MinValue " + number_text(*r.min);
    if (r.max && less(*r.max, def)) return "the default " + number_text(def) + " of " + name.text() + " is above its MaxValue " + number_text(*r.max);
    const Number low = format_min(format);
    const Number high = format_max(format);
    if (less(def, low) || less(high, def))
        return "the default " + number_text(def) + " of " + name.text() + " does not fit " + std::string(type_name) + " (" +
               bits_text(format.bit_size) + ": " + number_text(low) + " to " + number_text(high) + ")";
    return std::nullopt;
}

// Without MinValue/MaxValue (or their data) only a DefaultValue can be out of range: a default
// given as data is read as a bit pattern of the entry's width, which always fits the type. Most
// entries of real dictionaries are such, and are not read at all.
bool may_be_out_of_range(const EntryValues& values) {
    return values.default_value || values.min_value || values.min_data || values.max_value || values.max_data;
}

void check_range(RuleContext& context, const EntryValues& values, const EntryName& name, std::string_view type_name,
                 const BasicType* basic, std::uint64_t bits, SourcePos pos) {
    if (!basic || !basic->is_integer()) return;
    const std::uint64_t width = bits > 0 ? bits : basic->bit_size;
    if (width == 0 || width > 64) return;
    const ValueFormat format{width, basic->type_class == TypeClass::signed_integer};
    // Reported only when neither reading of the values is in range: a value is a bit pattern
    // or a plain number depending on the tool that wrote it, and the file does not say which.
    const std::optional<std::string> as_patterns = range_violation(read_values(values, format, true), format, name, type_name);
    if (!as_patterns || !range_violation(read_values(values, format, false), format, name, type_name)) return;
    context.report(pos, *as_patterns);
}

// Calls f(values, name, type name, basic type, bits, position) for every entry whose values
// `wanted` accepts: DataType SubItems with values, then the sub-entries of the objects by their
// layouts. Every sub-entry takes its values from the object's Info or from one of the Info's
// SubItems, so an object none of whose Infos `wanted` accepts is passed by without its layout.
template <class Wanted, class F>
void for_each_valued_entry(const EsiDocument& document, RuleContext& context, Wanted&& wanted, F&& f) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        const Dictionary& dictionary = *scope.dictionary;
        const TypeIndex& types = context.cache().types(&dictionary);
        const DictionaryIndex& objects = context.cache().objects(&dictionary);
        for (const auto& type : dictionary.data_types)
            for (const auto& item : type.sub_items) {
                if (!item.default_data && !item.default_value && !item.default_string && !item.max_value && !item.min_value) continue;
                const EntryValues values = values_of(item);
                if (!wanted(values)) continue;
                f(values, EntryName{nullptr, 0, false, &type, &item}, std::string_view(item.type), types.basic(item.type), item.bit_size,
                  item.pos);
            }
        for (const auto& object : dictionary.objects) {
            if (!object.info) continue;  // no values at all, for the object or its sub-entries
            const ObjectInfo& info = *object.info;
            if (!wanted(values_of(info)) &&
                std::none_of(info.sub_items.begin(), info.sub_items.end(), [&](const ObjectSubItemInfo& s) { return wanted(values_of(s.info)); }))
                continue;
            const ObjectLayout& layout = objects.layout(object);
            for (const auto& entry : layout.entries) {
                if (!entry.info) continue;
                const EntryValues values = values_of(*entry.info);
                if (!wanted(values)) continue;
                f(values, EntryName{&object, entry.subindex, layout.code == ObjectCode::var, nullptr, nullptr}, std::string_view(entry.type),
                  entry.basic, entry.bit_size, entry.info->pos);
            }
        }
    }
}

// ---- od-mandatory-object, od-mandatory-object-offline --------------------------------------

// Calls f(device, dictionary, missing object) for every mandatory object a CoE device's own
// Dictionary lacks. Only a device that describes its CoE dictionary in the ESI can be checked;
// many devices leave it to SDO information at run time.
template <class F>
void for_each_missing_mandatory_object(const EsiDocument& document, F&& f) {
    for (const auto& info : document.infos)
        for (const auto& device : info.devices) {
            if (!device.mailbox || !device.mailbox->coe) continue;
            const Dictionary* dictionary = device.dictionary();
            if (!dictionary || dictionary->objects.empty()) continue;
            for (const auto& mandatory : mandatory_objects)
                if (!dictionary->find_object(mandatory.index)) f(device, *dictionary, mandatory);
        }
}

// With SDO information (CoE@SdoInfo) a configuration tool reads the dictionary from the device,
// and the ESI Dictionary is an offline extract.
bool has_sdo_info(const Device& device) { return device.mailbox->coe->sdo_info.value_or(false); }

// Reports the missing mandatory objects of the devices with (or without) SDO information.
void report_missing_mandatory(const EsiDocument& document, RuleContext& context, bool sdo_info, std::string_view consequence) {
    for_each_missing_mandatory_object(document, [&](const Device& device, const Dictionary& dictionary, const MandatoryObject& mandatory) {
        if (has_sdo_info(device) != sdo_info) return;
        context.report(dictionary.pos, "the device has a CoE mailbox, but its Dictionary has no object " + object_address(mandatory.index) +
                                           " (" + std::string(mandatory.name) + "), which every CoE device must have; " +
                                           std::string(consequence));
    });
}

void check_mandatory_object(const EsiDocument& document, RuleContext& context) {
    report_missing_mandatory(document, context, false, "without SDO information this Dictionary is all a configuration tool knows of it");
}

constexpr Rule od_mandatory_object{
    .id = "od-mandatory-object",
    .default_severity = Severity::error,
    .summary = "The Dictionary of a CoE device without SDO information lacks object 0x1000 or 0x1018",
    .rationale =
        "Every CoE device has Device type (0x1000) and Identity (0x1018) (ETG.1000.6; CiA 301), and the conformance "
        "test tool reads both (CTT TF-2301). When the ESI describes the Dictionary, it must describe these objects too "
        "(SOES tutorial; kubabuda/EEPROM_generator adds both to every dictionary it generates). A device without SDO "
        "information (CoE@SdoInfo) cannot tell a configuration tool its objects at run time, so the ESI Dictionary is "
        "the whole description, and one without the mandatory objects describes no conformant device. With SDO "
        "information it is od-mandatory-object-offline's warning. Devices whose ESI has no Dictionary are not "
        "checked.",
    .bad_example = "<Mailbox><CoE SdoInfo=\"false\"/></Mailbox> and a Dictionary with objects but no #x1018",
    .good_example = "<Mailbox><CoE SdoInfo=\"false\"/></Mailbox> and a Dictionary with #x1000 and #x1018",
    .check = check_mandatory_object,
};

void check_mandatory_object_offline(const EsiDocument& document, RuleContext& context) {
    report_missing_mandatory(document, context, true, "the device has SDO information, so tools read it from the device");
}

constexpr Rule od_mandatory_object_offline{
    .id = "od-mandatory-object-offline",
    .default_severity = Severity::warning,
    .summary = "The offline Dictionary of a CoE device with SDO information lacks object 0x1000 or 0x1018",
    .rationale =
        "Every CoE device has Device type (0x1000) and Identity (0x1018) (ETG.1000.6; CiA 301). A device that "
        "declares SDO information (CoE@SdoInfo, ETG.2000) lists its objects to configuration tools at run time, and "
        "masters identify it by its SII, not by the ESI's 0x1018; the ESI Dictionary is then an offline extract, and "
        "one without the mandatory objects is incomplete but misleads no master (Elmo's boot-loader descriptions carry "
        "such a partial Dictionary). A warning; without SDO information it is od-mandatory-object's error.",
    .bad_example = "<Mailbox><CoE SdoInfo=\"true\"/></Mailbox> and a Dictionary with objects but no #x1018",
    .good_example = "<Mailbox><CoE SdoInfo=\"true\"/></Mailbox> and a Dictionary with #x1000 and #x1018",
    .check = check_mandatory_object_offline,
};

// ---- od-duplicate-object --------------------------------------------------------------------

// The first Object of that index that has an Index element (one without is the reader's finding).
const Object* first_declared(const Dictionary& dictionary, const DictionaryIndex& objects, std::uint32_t index) {
    const Object* first = objects.object(index);
    if (first && first->index_pos.line != 0) return first;
    for (const auto& object : dictionary.objects)
        if (object.index == index && object.index_pos.line != 0) return &object;
    return nullptr;
}

void check_duplicate_object(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        const DictionaryIndex& objects = context.cache().objects(scope.dictionary);
        for (const auto& object : scope.dictionary->objects) {
            if (object.index_pos.line == 0) continue;  // no Index: reported by the reader
            const Object* first = first_declared(*scope.dictionary, objects, object.index);
            if (first == &object) continue;
            context.report(object.index_pos, "Object " + object_address(object.index) + " is declared twice in this Dictionary",
                           {context.note(first->index_pos, "first declared here")},
                           remove_identical_copy(document, first->pos, object.pos, "remove the identical copy of the Object"));
        }
    }
}

constexpr Rule od_duplicate_object{
    .id = "od-duplicate-object",
    .default_severity = Severity::error,
    .summary = "Two Objects of one Dictionary share an index",
    .rationale =
        "An index addresses one object (ETG.1000.6 object dictionary). With two declarations a master shows one and "
        "the other is unreachable; slave tables generated from the ESI have two entries for one index and SDO lookups "
        "such as SDO_findobject in SOES soes/esc_coe.c (a binary search over the sorted list) pick either.",
    .bad_example = "<Object><Index>#x2000</Index>…</Object><Object><Index>#x2000</Index>…</Object>",
    .good_example = "<Object><Index>#x2000</Index>…</Object><Object><Index>#x2001</Index>…</Object>",
    .check = check_duplicate_object,
    .fix = "removes the second Object when it is a byte-identical copy of the first",
};

// ---- od-flags-value -------------------------------------------------------------------------

void check_flags_value(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        for_each_flags(*scope.dictionary, [&](const ObjectFlags& flags) {
            if (flags.access && !is_access(*flags.access))
                context.report(flags.pos, "Access '" + *flags.access + "' is not ro, rw or wo");
            if (flags.pdo_mapping && !is_pdo_mapping(*flags.pdo_mapping))
                context.report(flags.pos, "PdoMapping '" + *flags.pdo_mapping + "' is not R, T, RT or TR (lower case for optional mapping)");
            if (flags.category && !is_category(*flags.category))
                context.report(flags.pos, "Category '" + *flags.category + "' is not m, o or c");
        });
    }
}

constexpr Rule od_flags_value{
    .id = "od-flags-value",
    .default_severity = Severity::error,
    .summary = "An Access, PdoMapping or Category value the schema does not allow",
    .rationale =
        "Flags/Access is ro, rw or wo; Flags/PdoMapping is R, T, RT or TR (lower case for optional mapping); "
        "Flags/Category is m, o or c (ETG.2000 EtherCATBase.xsd ObjectType/Flags). Other spellings (RW, R/W, rx) are "
        "read as 'no access' or 'not mappable' by tools that follow the schema.",
    .bad_example = "<Flags><Access>RW</Access><PdoMapping>rx</PdoMapping></Flags>",
    .good_example = "<Flags><Access>rw</Access><PdoMapping>R</PdoMapping></Flags>",
    .check = check_flags_value,
};

// ---- od-default-length ----------------------------------------------------------------------

void check_default_length(const EsiDocument& document, RuleContext& context) {
    for_each_valued_entry(document, context, has_lengths, [&](const EntryValues& values, const EntryName& name, std::string_view type_name,
                                                              const BasicType* basic, std::uint64_t bits, SourcePos pos) {
        check_lengths(context, values, name, type_name, basic, bits, pos);
    });
}

constexpr Rule od_default_length{
    .id = "od-default-length",
    .default_severity = Severity::warning,
    .summary = "DefaultData/MinData/MaxData whose length differs from the entry's size",
    .rationale =
        "DefaultData, MinData and MaxData are the value's bytes as an SDO transfers them (ETG.2000 ObjectInfoType), "
        "so they have exactly the entry's size in bytes; strings and byte arrays may be shorter than their maximum. A "
        "longer or shorter value is truncated or padded differently by each tool (KickCAT 'data default size "
        "mismatch'; kubabuda/EEPROM_generator #2 on string lengths). DefaultString must fit STRING(n).",
    .bad_example =
        "<Object><Index>#x1018</Index>… <SubItem><Name>Vendor ID</Name><Info><DefaultData>E40A</DefaultData>…",
    .good_example =
        "<Object><Index>#x1018</Index>… <SubItem><Name>Vendor ID</Name><Info><DefaultData>E40A0000</DefaultData>…",
    .check = check_default_length,
};

// ---- od-default-range -----------------------------------------------------------------------

void check_default_range(const EsiDocument& document, RuleContext& context) {
    for_each_valued_entry(document, context, may_be_out_of_range, [&](const EntryValues& values, const EntryName& name,
                                                                       std::string_view type_name, const BasicType* basic,
                                                                       std::uint64_t bits, SourcePos pos) {
        check_range(context, values, name, type_name, basic, bits, pos);
    });
}

constexpr Rule od_default_range{
    .id = "od-default-range",
    .default_severity = Severity::warning,
    .summary = "A default value outside MinValue/MaxValue or outside its type",
    .rationale =
        "A device starts with its default; a default that its own limits forbid (or that does not fit the type, such as "
        "300 for a USINT) is either rejected by the firmware's range check at the first SDO write-back or silently "
        "truncated. MinValue above MaxValue is reported too. Limits of signed objects written as bit patterns "
        "(#xfff80001 for a DINT) are read as two's complement (ETG.2000 ObjectInfoType; SSC Default/Min/Max columns, "
        "ET9300 §13).",
    .bad_example = "<Type>USINT</Type>… <Info><DefaultValue>300</DefaultValue></Info>",
    .good_example = "<Type>USINT</Type>… <Info><DefaultValue>30</DefaultValue></Info>",
    .check = check_default_range,
};

}  // namespace

void add_od_object(std::vector<Rule>& out) {
    out.insert(out.end(), {
        od_mandatory_object,
        od_mandatory_object_offline,
        od_duplicate_object,
        od_flags_value,
        od_default_length,
        od_default_range,
    });
}

}  // namespace esi::rules
