// Rules of the pdo area on PDO entries by themselves: the DataType name, BitLen against the
// DataType, padding entries and byte alignment.
#include <vector>

#include "check/areas.hpp"
#include "check/od_text.hpp"
#include "check/pdo_entry_type.hpp"
#include "check/pdo_scope.hpp"
#include "check/rule_cache.hpp"
#include "check/source_edit.hpp"
#include "esi/text_distance.hpp"

namespace esi::rules {

namespace {

template <class F>
void for_each_entry(const EsiDocument& document, RuleContext& context, F&& f) {
    for (const auto& scope : context.cache().pdo_scopes(document))
        scope.for_each_pdo([&](const Pdo& pdo) {
            for (const auto& entry : pdo.entries) f(scope, pdo, entry);
        });
}

// The same, with what the entry's DataType means under its owner's Dictionary.
template <class F>
void for_each_typed_entry(const EsiDocument& document, RuleContext& context, F&& f) {
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        PdoEntryFacts& entries = context.cache().pdo_entries(scope);
        for (std::size_t i = 0; i < entries.size(); ++i) f(scope, entries.type(i), entries.entry(i));
    }
}

SourcePos data_type_or_entry(const PdoEntry& entry) { return entry.data_type_pos.line ? entry.data_type_pos : entry.pos; }

std::vector<std::string_view> basic_type_names() {
    std::vector<std::string_view> names;
    for (const auto& t : basic_types()) names.push_back(t.esi_name);
    return names;
}

// ---- pdo-entry-type-unknown, pdo-entry-type-spelling ----------------------------------------

void check_entry_type_unknown(const EsiDocument& document, RuleContext& context) {
    static const std::vector<std::string_view> names = basic_type_names();
    for_each_typed_entry(document, context, [&](const PdoScope& scope, const EntryType& type, const PdoEntry& entry) {
        if (!type.present) {
            // Padding needs no DataType; a mapped value does, and an empty element says nothing.
            if (entry.data_type && !entry.is_padding())
                context.report(data_type_or_entry(entry), entry_label(entry) + " has an empty DataType");
            return;
        }
        // A known non-standard spelling is pdo-entry-type-spelling's.
        if (type.known || !type.standard_name.empty()) return;
        const std::string& text = *entry.data_type;
        std::string message = entry_label(entry) + " has DataType '" + text + "', which is neither a basic ESI type nor " +
                              (scope.dictionary ? "defined in the Dictionary" : "defined anywhere (there is no Dictionary)");
        if (const std::string suggestion = closest_match(text, names); !suggestion.empty())
            message += "; did you mean '" + suggestion + "'?";
        context.report(data_type_or_entry(entry), std::move(message));
    });
}

constexpr Rule pdo_entry_type_unknown{
    .id = "pdo-entry-type-unknown",
    .default_severity = Severity::error,
    .summary = "A PDO entry's DataType is not a type any tool knows",
    .rationale =
        "Masters type process variables from the entry's DataType. A name that is neither a basic ESI type (ETG.2000, "
        "ET9300 Table 22: BOOL, USINT, UINT, UDINT, …), nor defined in the Dictionary, nor a known spelling of a "
        "basic type (pdo-entry-type-spelling) cannot be typed: the configuration tool rejects the variable or makes "
        "it an untyped byte field. An empty DataType on a mapped entry is reported too (padding needs none).",
    .bad_example = "<Entry><Index>#x6041</Index><BitLen>16</BitLen><DataType>UNIT</DataType></Entry>",
    .good_example = "<Entry><Index>#x6041</Index><BitLen>16</BitLen><DataType>UINT</DataType></Entry>",
    .check = check_entry_type_unknown,
};

void check_entry_type_spelling(const EsiDocument& document, RuleContext& context) {
    for_each_typed_entry(document, context, [&](const PdoScope&, const EntryType& type, const PdoEntry& entry) {
        if (!type.present || type.standard_name.empty()) return;
        const std::string& text = *entry.data_type;
        const bool whole = type.nonstandard_name == trim(text);
        // The whole DataType is the alias: its standard name is certain (a safe fix).
        std::optional<Fix> fix;
        if (whole && entry.data_type_pos.known())
            fix = replace_element_text(document, entry.data_type_pos, trim(text), std::string(type.standard_name),
                                       "write the standard type name");
        context.report(data_type_or_entry(entry), entry_label(entry) + " has DataType '" + text + "'" +
                                                      (whole ? ", which" : ": '" + std::string(type.nonstandard_name) + "'") +
                                                      " is not an ESI type name; the standard name is '" +
                                                      std::string(type.standard_name) + "'",
                       std::move(fix));
    });
}

constexpr Rule pdo_entry_type_spelling{
    .id = "pdo-entry-type-spelling",
    .default_severity = Severity::warning,
    .summary = "A PDO entry's DataType is a non-standard spelling of a basic type (UINT16 for UINT)",
    .rationale =
        "ESI type names are the IEC 61131-3 style names of ETG.2000 and ET9300 Table 22 (USINT, UINT, UDINT, SINT, "
        "INT, DINT, REAL, LREAL, …). C-style and TwinCAT spellings (UINT8/UINT16/UINT32/UINT64, INT8…INT64, FLOAT, "
        "DOUBLE) and CoE names (UNSIGNED16) name the same types: the IgH EtherCAT master's `ethercat xml` command "
        "writes UINT<bits> itself (tool/CommandXml.cpp; the bus-config.xml dumps in DiamondLightSource/ethercat), "
        "pollen-robotics/pyesi writes UINT8/UINT16, and BitLen "
        "carries the layout either way. Tools that only know the standard names lose the variable's type, so the "
        "message names the standard spelling; the other pdo rules judge the entry as that type.",
    .bad_example = "<Entry><Index>#x6041</Index><BitLen>16</BitLen><DataType>UINT16</DataType></Entry>",
    .good_example = "<Entry><Index>#x6041</Index><BitLen>16</BitLen><DataType>UINT</DataType></Entry>",
    .check = check_entry_type_spelling,
    .fix = "writes the standard name (UINT for UINT16) when the whole DataType is the alias",
};

// ---- pdo-entry-bitlen-type ------------------------------------------------------------------

void check_entry_bitlen_type(const EsiDocument& document, RuleContext& context) {
    for_each_typed_entry(document, context, [&](const PdoScope&, const EntryType& type, const PdoEntry& entry) {
        // BitLen 0 is a missing or unreadable BitLen (the reader reports it) or an empty slot.
        if (entry.is_padding() || entry.bit_len == 0 || entry.bit_len_pos.line == 0) return;
        if (!type.known || type.bit_size == 0 || type.bit_size == entry.bit_len) return;
        context.report(entry.bit_len_pos, entry_label(entry) + " has BitLen " + std::to_string(entry.bit_len) + " but " +
                                              *entry.data_type + " is " + bits_text(type.bit_size));
    });
}

constexpr Rule pdo_entry_bitlen_type{
    .id = "pdo-entry-bitlen-type",
    .default_severity = Severity::error,
    .summary = "A PDO entry's BitLen disagrees with its DataType",
    .rationale =
        "BitLen is the width the entry occupies in the process image and DataType says how to read it; UINT is 16 "
        "bits, DINT 32, BITn n (ET9300 Table 22; ETG.1000.6 data types). A mismatch shifts every later variable in "
        "the image or truncates the value. The manuals of the item C series and Afag SE-Power servo controllers state "
        "it outright: BitLen 'muss immer dem Typ … entsprechen' (Tabelle 14). Padding entries (Index 0) are exempt.",
    .bad_example = "<Entry><Index>#x6064</Index><BitLen>16</BitLen><DataType>DINT</DataType></Entry>",
    .good_example = "<Entry><Index>#x6064</Index><BitLen>32</BitLen><DataType>DINT</DataType></Entry>",
    .check = check_entry_bitlen_type,
};

// ---- pdo-padding-subindex -------------------------------------------------------------------

void check_padding_subindex(const EsiDocument& document, RuleContext& context) {
    for_each_entry(document, context, [&](const PdoScope&, const Pdo&, const PdoEntry& entry) {
        if (!entry.is_padding() || entry.effective_subindex() == 0) return;
        context.report(entry.pos, "Padding entry (Index 0) has SubIndex " + std::to_string(entry.effective_subindex()) +
                                      "; a gap in a PDO is mapped as #x0000:00 with only its BitLen");
    });
}

constexpr Rule pdo_padding_subindex{
    .id = "pdo-padding-subindex",
    .default_severity = Severity::warning,
    .summary = "A padding entry (Index 0) with a SubIndex other than 0",
    .rationale =
        "Gaps in a PDO are mapped as Index 0, SubIndex 0 with the gap's BitLen (OpenEtherCATsociety/SOEM #297: "
        "fillers are 0x0000:00; SSC pad_x entries). A non-zero SubIndex turns the filler into the mapping entry "
        "0x0000:nn, which some slave stacks reject when the mapping is downloaded. Padding needs neither a DataType "
        "nor a Name.",
    .bad_example = "<Entry><Index>#x0</Index><SubIndex>1</SubIndex><BitLen>7</BitLen></Entry>",
    .good_example = "<Entry><Index>#x0</Index><BitLen>7</BitLen></Entry>",
    .check = check_padding_subindex,
};

// ---- pdo-padding-bitlen-zero ----------------------------------------------------------------

void check_padding_bitlen_zero(const EsiDocument& document, RuleContext& context) {
    for_each_entry(document, context, [&](const PdoScope&, const Pdo& pdo, const PdoEntry& entry) {
        // BitLen 0 without a BitLen element is a missing BitLen, which the reader reports.
        if (!entry.is_padding() || entry.bit_len != 0 || entry.bit_len_pos.line == 0) return;
        context.report(entry.bit_len_pos, "Padding entry (Index 0) of " + std::string(pdo.element_name()) + " " + object_address(pdo.index) +
                                              " has BitLen 0; it fills no gap, and a master that writes the mapping "
                                              "downloads an entry of length 0");
    });
}

constexpr Rule pdo_padding_bitlen_zero{
    .id = "pdo-padding-bitlen-zero",
    .default_severity = Severity::warning,
    .summary = "A padding entry (Index 0) with BitLen 0",
    .rationale =
        "A padding entry reserves BitLen bits of a PDO to align what follows (mapped as 0x0000:00 with the gap's "
        "length; OpenEtherCATsociety/SOEM #297). With BitLen 0 it reserves nothing, yet it is still a mapping entry: "
        "it counts in the mapping object's sub-index 0 and in the SII PDO category, and a master that configures the "
        "mapping (CoE PdoConfig) downloads an entry of length 0, which a slave stack may refuse like any mapping "
        "entry it does not expect (ETG.1000.6 PDO mapping). The process image is the same with or without it: a "
        "warning; remove the entry. Generators leave such entries when the data already ends on a byte boundary "
        "(Beckhoff BKxxxxModules.xml, module KL9191, in DiamondLightSource/ethercat etc/xml/).",
    .bad_example = "<Entry><Index>#x0</Index><BitLen>0</BitLen></Entry>",
    .good_example = "<Entry><Index>#x0</Index><BitLen>2</BitLen></Entry> (or no entry)",
    .check = check_padding_bitlen_zero,
};

// ---- pdo-entry-alignment --------------------------------------------------------------------

void check_entry_alignment(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        scope.for_each_pdo([&](const Pdo& pdo) {
            std::uint64_t offset = 0;
            for (const auto& entry : pdo.entries) {
                if (!entry.is_padding() && entry.bit_len >= 8 && offset % 8 != 0) {
                    // One finding per PDO: every later entry is shifted by the same missing padding.
                    context.report(entry.pos, entry_label(entry) + " (" + bits_text(entry.bit_len) + ") starts at bit " +
                                                  std::to_string(offset) + " of " + std::string(pdo.element_name()) + " " +
                                                  object_address(pdo.index) +
                                                  ", not on a byte boundary; pad the entries before it to a whole byte");
                    return;
                }
                offset += entry.bit_len;
            }
        });
    }
}

constexpr Rule pdo_entry_alignment{
    .id = "pdo-entry-alignment",
    .default_severity = Severity::warning,
    .summary = "An entry of 8 bits or more does not start on a byte boundary",
    .rationale =
        "Values of a byte or more should start on a byte boundary of the PDO; many slave stacks copy process data "
        "byte-wise and masters map variables to byte offsets, so a 16-bit value at bit 3 is either rejected or read "
        "shifted. The SSC inserts padding for this reason ('append padding byte … (basic process data has odd word "
        "length)', SSC cia402appl.h). Only the first misaligned entry of a PDO is reported, as the others follow from "
        "it.",
    .bad_example =
        "<Entry><Index>#x6000</Index><SubIndex>1</SubIndex><BitLen>1</BitLen>…</Entry><Entry><Index>#x6001</Index><BitLen>16</BitLen>…",
    .good_example =
        "<Entry><Index>#x6000</Index><SubIndex>1</SubIndex><BitLen>1</BitLen>…</Entry><Entry><Index>#x0</Index><BitLen>7</BitLen></Entry>"
        "<Entry><Index>#x6001</Index><BitLen>16</BitLen>…",
    .check = check_entry_alignment,
};

}  // namespace

void add_pdo_entry(std::vector<Rule>& out) {
    out.insert(out.end(), {
        pdo_entry_type_unknown,
        pdo_entry_type_spelling,
        pdo_entry_bitlen_type,
        pdo_padding_subindex,
        pdo_padding_bitlen_zero,
        pdo_entry_alignment,
    });
}

}  // namespace esi::rules
