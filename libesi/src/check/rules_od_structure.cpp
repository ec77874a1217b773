// Rules of the od area about the shape of the offline Dictionary as a whole: the type of the
// entry count every record and array starts with, and how many Dictionaries a device has.
#include <string>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "check/od_scope.hpp"
#include "esi/number.hpp"

namespace esi::rules {

namespace {

// ---- od-subindex0-type ----------------------------------------------------------------------

// The spellings of UNSIGNED8 the catalogue knows (pdo-entry-type-spelling, od-nonstandard-type-name).
bool is_unsigned8(std::string_view type) { return type == "USINT" || type == "UINT8" || type == "UNSIGNED8"; }

// CiA 301 before 4.02 had one object whose sub-index 0 is not a count: 0x1004 'Number of PDOs
// supported', an UNSIGNED32 with the RxPDOs in its low and the TxPDOs in its high 16 bits (Beckhoff
// AX2000-B110 still describes it so).
constexpr std::uint32_t number_of_pdos_supported = 0x1004;

// The manufacturer-specific area (ETG.1000.6, CiA 301): the vendor defines these objects, and some
// define sub-index 0 as their first element (STÖBER's array parameters such as A252 at 0x20FC, by
// the STÖBER EtherCAT manuals). Only objects outside it are held to the count.
bool manufacturer_specific(std::uint32_t index) { return index >= 0x2000 && index <= 0x5FFF; }

// The SubItem holding a record's entry count: its first with SubIdx 0; nullptr when none.
const DataTypeSubItem* count_item(const DataType& type) {
    for (const auto& item : type.sub_items)
        if (item.subindex == 0u) return &item;
    return nullptr;
}

// Whether an object of the standardised areas has this type.
bool used_by_standard_object(const Dictionary& dictionary, std::string_view type_name) {
    for (const auto& object : dictionary.objects)
        if (!manufacturer_specific(object.index) && object.index != number_of_pdos_supported && trim(object.type) == type_name) return true;
    return false;
}

void check_subindex0_type(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().dictionary_scopes(document)) {
        for (const auto& type : scope.dictionary->data_types) {
            // Only records and array holders (more than one SubItem) have an entry count at sub-index 0.
            if (type.sub_items.size() < 2) continue;
            const DataTypeSubItem* item = count_item(type);
            if (!item) continue;
            const std::string_view name = trim(item->type);
            if (is_unsigned8(name) && item->bit_size == 8) continue;
            // Looked for only now: nearly every count is right, and then no object needs a look.
            if (!used_by_standard_object(*scope.dictionary, type.name)) continue;
            context.report(item->pos, "DataType " + type.name + ": sub-index 0 ('" + item->name + "') is " +
                                          (name.empty() ? std::string("untyped") : std::string(name)) + " of " +
                                          std::to_string(item->bit_size) +
                                          " bits; it holds the number of entries, which is USINT (UNSIGNED8, 8 bits)");
        }
    }
}

constexpr Rule od_subindex0_type{
    .id = "od-subindex0-type",
    .default_severity = Severity::warning,
    .summary = "Sub-index 0 of a record or array that is not USINT (8 bits)",
    .rationale =
        "Sub-index 0 of a record or array object holds the number of its entries, an UNSIGNED8 (ETG.1000.6 object "
        "dictionary; CiA 301 'highest sub-index supported'), and complete access transfers it as one byte padded to "
        "two. Slave stacks keep it in one byte: SOES reads it as a uint8_t (COE_maxSub in soes/esc_coe.c) and "
        "aborts an SDO download whose length differs from the entry's (ABORT_TYPEMISMATCH, 0x06070010), so a "
        "start-up value sized by a UINT sub-index 0 of the description is refused. The device serves its own "
        "sub-index 0 either way, so an offline Dictionary that says UINT (UTRIO UC20-RTU-EC-A declares 31 records so) "
        "misleads tools, not the device: a warning. Objects of the manufacturer-specific area (0x2000-0x5FFF) are "
        "not judged, since a vendor may define their sub-index 0 as a first element (STÖBER's array parameters), nor "
        "0x1004, whose sub-index 0 was the UNSIGNED32 'Number of PDOs supported' before CiA 301 4.02.",
    .bad_example = "<SubItem><SubIdx>0</SubIdx><Name>Number of entries</Name><Type>UINT</Type><BitSize>16</BitSize>…",
    .good_example = "<SubItem><SubIdx>0</SubIdx><Name>Number of entries</Name><Type>USINT</Type><BitSize>8</BitSize>…",
    .check = check_subindex0_type,
};

// ---- od-dictionary-count --------------------------------------------------------------------

void check_dictionary_count(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos)
        for (const auto& device : info.devices) {
            const Profile* first = nullptr;
            for (const auto& profile : device.profiles) {
                if (!profile.dictionary && !profile.dictionary_file) continue;
                if (!first) {
                    first = &profile;
                    continue;
                }
                context.report(profile.pos,
                               "Device '" + device.type.text +
                                   "' has a second offline Dictionary; tools read the first Profile's, so the objects "
                                   "described here are not seen",
                               {context.note(first->pos, "the Profile whose Dictionary is read")});
            }
        }
}

constexpr Rule od_dictionary_count{
    .id = "od-dictionary-count",
    .default_severity = Severity::warning,
    .summary = "A device with more than one offline Dictionary",
    .rationale =
        "A device has one object dictionary (ETG.1000.6), and the conformance test counts the offline dictionaries of "
        "a device description (CTT TF-1300 1-4 'Number of Offline Dictionaries'). The schema lets every Profile of a "
        "device carry a Dictionary or DictionaryFile; configuration tools, and libesi (esi-net, the od- and pdo- "
        "rules), read the first one, so the objects of a second are not seen by anyone. None of the vendors' files "
        "has two; which count the test accepts is not published, so a warning: merge the objects into one "
        "Dictionary.",
    .bad_example = "<Profile><ProfileNo>5001</ProfileNo><Dictionary>…</Dictionary></Profile><Profile><Dictionary>…</Dictionary></Profile>",
    .good_example = "<Profile><ProfileNo>5001</ProfileNo><Dictionary>… all objects …</Dictionary></Profile>",
    .check = check_dictionary_count,
};

}  // namespace

void add_od_structure(std::vector<Rule>& out) {
    out.insert(out.end(), {
        od_subindex0_type,
        od_dictionary_count,
    });
}

}  // namespace esi::rules
