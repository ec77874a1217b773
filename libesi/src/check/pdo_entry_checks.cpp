// pdo-… checks on PDO entries by themselves: the DataType name, BitLen against the DataType,
// padding entries and byte alignment.
#include <vector>

#include "check/od_text.hpp"
#include "check/pdo_checks.hpp"
#include "check/pdo_entry_type.hpp"
#include "check/pdo_scope.hpp"
#include "check/rule_cache.hpp"
#include "esi/text_distance.hpp"

namespace esi::rules::pdo {

namespace {

template <class F>
void for_each_entry(const EsiDocument& document, F&& f) {
    for (const auto& scope : pdo_scopes(document))
        scope.for_each_pdo([&](const Pdo& pdo) {
            for (const auto& entry : pdo.entries) f(scope, pdo, entry);
        });
}

// The same, with what DataTypes mean under the owner's Dictionary at hand.
template <class F>
void for_each_typed_entry(const EsiDocument& document, RuleContext& context, F&& f) {
    for (const auto& scope : pdo_scopes(document)) {
        EntryTypes& types = context.cache().entry_types(scope.dictionary);
        for (const auto* list : {scope.rx_pdos, scope.tx_pdos})
            for (const auto& pdo : *list)
                for (const auto& entry : pdo.entries) f(scope, types, entry);
    }
}

SourcePos data_type_or_entry(const PdoEntry& entry) { return entry.data_type_pos.line ? entry.data_type_pos : entry.pos; }

std::vector<std::string_view> basic_type_names() {
    std::vector<std::string_view> names;
    for (const auto& t : basic_types()) names.push_back(t.esi_name);
    return names;
}

}  // namespace

void check_entry_type_unknown(const EsiDocument& document, RuleContext& context) {
    static const std::vector<std::string_view> names = basic_type_names();
    for_each_typed_entry(document, context, [&](const PdoScope& scope, EntryTypes& types, const PdoEntry& entry) {
        const EntryType& type = types.of(entry);
        if (!type.present) {
            // Padding needs no DataType; a mapped value does, and an empty element says nothing.
            if (entry.data_type && !entry.is_padding())
                context.report(data_type_or_entry(entry), entry_label(entry) + " has an empty DataType");
            return;
        }
        const std::string& text = *entry.data_type;
        if (!type.standard_name.empty()) {
            const bool whole = type.nonstandard_name == trim(text);
            context.report(data_type_or_entry(entry), entry_label(entry) + " has DataType '" + text + "'" +
                                                          (whole ? ", which" : ": '" + std::string(type.nonstandard_name) + "'") +
                                                          " is not an ESI type name; the standard name is '" +
                                                          std::string(type.standard_name) + "'");
            return;
        }
        if (type.known) return;
        std::string message = entry_label(entry) + " has DataType '" + text + "', which is neither a basic ESI type nor " +
                              (scope.dictionary ? "defined in the Dictionary" : "defined anywhere (there is no Dictionary)");
        if (const std::string suggestion = closest_match(text, names); !suggestion.empty())
            message += "; did you mean '" + suggestion + "'?";
        context.report(data_type_or_entry(entry), std::move(message));
    });
}

void check_entry_bitlen_type(const EsiDocument& document, RuleContext& context) {
    for_each_typed_entry(document, context, [&](const PdoScope&, EntryTypes& types, const PdoEntry& entry) {
        // BitLen 0 is a missing or unreadable BitLen (the reader reports it) or an empty slot.
        if (entry.is_padding() || entry.bit_len == 0 || entry.bit_len_pos.line == 0) return;
        const EntryType& type = types.of(entry);
        if (!type.known || type.bit_size == 0 || type.bit_size == entry.bit_len) return;
        context.report(entry.bit_len_pos, entry_label(entry) + " has BitLen " + std::to_string(entry.bit_len) + " but " +
                                              *entry.data_type + " is " + bits_text(type.bit_size));
    });
}

void check_padding_subindex(const EsiDocument& document, RuleContext& context) {
    for_each_entry(document, [&](const PdoScope&, const Pdo&, const PdoEntry& entry) {
        if (!entry.is_padding() || entry.effective_subindex() == 0) return;
        context.report(entry.pos, "Padding entry (Index 0) has SubIndex " + std::to_string(entry.effective_subindex()) +
                                      "; a gap in a PDO is mapped as #x0000:00 with only its BitLen");
    });
}

void check_entry_alignment(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : pdo_scopes(document)) {
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

}  // namespace esi::rules::pdo
