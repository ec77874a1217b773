// Rules of the pdo area that compare the PDO description against the defaults the Dictionary
// gives the CoE objects that describe the same thing over SDO: the SM PDO assignment objects
// 0x1C10-0x1C2F (0x1C12 for SM2, 0x1C13 for SM3) and the mapping objects 0x1600-0x17FF /
// 0x1A00-0x1BFF (ETG.1000.6 CoE communication area). A master that reads the objects (PdoUpload)
// and one that reads the ESI must end up with the same process image; SOEM #402 shows what a
// swapped 0x1C12 does.
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "check/areas.hpp"
#include "check/od_text.hpp"
#include "check/od_values.hpp"
#include "check/pdo_scope.hpp"
#include "check/queries.hpp"
#include "check/rule_cache.hpp"

namespace esi::rules {

namespace {

constexpr std::uint32_t first_assignment_object = 0x1C10;  // SM0; 0x1C10 + n for SM n
constexpr std::uint32_t last_assignment_object = 0x1C2F;

std::optional<std::uint64_t> entry_default(const ObjectEntry& entry) {
    if (!entry.info || entry.bit_size == 0 || entry.bit_size > 64) return std::nullopt;
    const std::optional<Number> value = default_number(*entry.info, ValueFormat{entry.bit_size, false});
    if (!value || value->negative) return std::nullopt;
    return value->magnitude;
}

// The defaults of sub-indices 1..n of an array/record object, n being the default of
// sub-index 0 when given. nullopt when the object states no such defaults.
std::optional<std::vector<std::uint64_t>> listed_defaults(const ObjectLayout& layout) {
    // The first entry of each sub-index; only the part up to the highest sub-index is cleared.
    std::array<const ObjectEntry*, 256> by_subindex;
    std::uint32_t highest = 0;
    for (const auto& e : layout.entries)
        if (e.subindex < by_subindex.size()) highest = std::max(highest, e.subindex);
    std::fill(by_subindex.begin(), by_subindex.begin() + highest + 1, nullptr);
    for (const auto& e : layout.entries)
        if (e.subindex < by_subindex.size() && !by_subindex[e.subindex]) by_subindex[e.subindex] = &e;
    const ObjectEntry* count_entry = by_subindex[0];
    const std::optional<std::uint64_t> count = count_entry ? entry_default(*count_entry) : std::nullopt;
    std::vector<std::uint64_t> values;
    bool any = count.has_value();
    for (std::uint32_t sub = 1; sub <= 255; ++sub) {
        if (count && sub > *count) break;
        const ObjectEntry* e = sub <= highest ? by_subindex[sub] : nullptr;
        const std::optional<std::uint64_t> value = e ? entry_default(*e) : std::nullopt;
        if (!value) {
            if (count) return std::nullopt;  // counted, but a counted entry has no default
            break;
        }
        any = true;
        values.push_back(*value);
    }
    if (!any) return std::nullopt;
    if (!count)
        while (!values.empty() && values.back() == 0) values.pop_back();
    return values;
}

std::string index_list(const std::vector<std::uint64_t>& values) {
    if (values.empty()) return "nothing";
    std::string out;
    for (const auto v : values) {
        if (!out.empty()) out += ", ";
        out += object_address(static_cast<std::uint32_t>(v));
    }
    return out;
}

SourcePos info_or_object(const Object& object) { return object.info ? object.info->pos : object.pos; }

std::uint64_t mapping_value(const PdoEntry& entry) {
    return (std::uint64_t{entry.index} << 16) | (std::uint64_t{entry.effective_subindex() & 0xFF} << 8) | (entry.bit_len & 0xFF);
}

void strip_trailing_padding(std::vector<std::uint64_t>& values) {
    while (!values.empty() && (values.back() >> 8) == 0) values.pop_back();
}

std::string mapping_text(std::uint64_t value) {
    const auto index = static_cast<std::uint32_t>((value >> 16) & 0xFFFF);
    const auto subindex = static_cast<std::uint32_t>((value >> 8) & 0xFF);
    return entry_address(index, subindex) + " (" + bits_text(value & 0xFF) + ")";
}

// ---- pdo-assign-default ---------------------------------------------------------------------

void check_assign_default(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        // Modular devices add module PDOs to the assignment as modules are plugged in.
        if (!scope.device || scope.device->slots || !scope.dictionary) continue;
        const DictionaryIndex& dictionary = context.cache().objects(scope.dictionary);
        for (std::uint32_t index = first_assignment_object; index <= last_assignment_object; ++index) {
            const Object* object = dictionary.object(index);
            if (!object) continue;
            const std::optional<std::vector<std::uint64_t>> listed = listed_defaults(*dictionary.layout(index));
            if (!listed) continue;
            std::vector<std::uint64_t> assigned;
            for (const auto& value : *listed)
                if (value != 0) assigned.push_back(value);  // 0 marks an empty entry
            const std::uint32_t sm = index - first_assignment_object;
            std::vector<std::uint64_t> expected;
            bool slot_dependent = false;
            scope.for_each_pdo([&](const Pdo& pdo) {
                if (pdo.sm == sm && !pdo.index_invalid) expected.push_back(pdo.index);
                slot_dependent = slot_dependent || (pdo.sm == sm && depends_on_slot(pdo));
            });
            // The order of the PDOs in the file is not an assignment order (PdoOrder is), so
            // only the sets are compared.
            if (slot_dependent || std::is_permutation(assigned.begin(), assigned.end(), expected.begin(), expected.end())) continue;
            context.report(info_or_object(*object),
                           "the default of " + object_address(index) + " (SM" + std::to_string(sm) + " PDO assignment) lists " +
                               index_list(assigned) + ", but the PDOs with Sm=\"" + std::to_string(sm) + "\" are " + index_list(expected));
        }
    }
}

constexpr Rule pdo_assign_default{
    .id = "pdo-assign-default",
    .default_severity = Severity::warning,
    .summary = "The default of 0x1C12/0x1C13 differs from the PDOs assigned by Sm=",
    .rationale =
        "PDOs with Sm=\"n\" are assigned to SM n by default; the Dictionary states the same assignment as the default "
        "of object 0x1C10+n (0x1C12 for SM2, 0x1C13 for SM3; ETG.1000.6). A master that uploads the assignment "
        "(PdoUpload) and one that takes it from the ESI then build different process images; SSC-generated firmware "
        "with byte-swapped or stale 0x1C12 defaults is a classic field failure (OpenEtherCATsociety/SOEM #402: "
        "'reference to the PDO mapping objects is a uint16_t but the bytes are swapped'). Modular devices are "
        "skipped: their assignment grows with the plugged modules. The order is not compared, only which PDOs are "
        "assigned.",
    .bad_example = "<RxPdo Sm=\"2\"><Index>#x1600</Index>… with 0x1C12 default listing #x1601",
    .good_example = "<RxPdo Sm=\"2\"><Index>#x1600</Index>… with 0x1C12 default listing #x1600",
    .check = check_assign_default,
};

// ---- pdo-mapping-default --------------------------------------------------------------------

void check_mapping_default(const EsiDocument& document, RuleContext& context) {
    for (const auto& scope : context.cache().pdo_scopes(document)) {
        if (!scope.device || !scope.dictionary) continue;
        const DictionaryIndex& dictionary = context.cache().objects(scope.dictionary);
        scope.for_each_pdo([&](const Pdo& pdo) {
            if (pdo.index_invalid || depends_on_slot(pdo)) return;
            const Object* object = dictionary.object(pdo.index);
            if (!object) return;
            for (const auto& entry : pdo.entries)
                if (entry.index_invalid || depends_on_slot(entry)) return;
            // A PDO without entries is a placeholder for a mapping configured at run time.
            if (pdo.entries.empty()) return;
            std::optional<std::vector<std::uint64_t>> listed = listed_defaults(*dictionary.layout(pdo.index));
            if (!listed) return;
            std::vector<std::uint64_t> defaults = std::move(*listed);
            std::vector<std::uint64_t> declared_values;
            declared_values.reserve(pdo.entries.size());
            for (const auto& entry : pdo.entries) declared_values.push_back(mapping_value(entry));
            // Trailing padding (rounding the PDO up to whole bytes) is left out on one side by some
            // vendors (Beckhoff EL2xxx: four BOOLs in the ESI, plus a 4-bit gap in 0x1600).
            strip_trailing_padding(defaults);
            strip_trailing_padding(declared_values);
            const auto pdo_name = [&] { return std::string(pdo.element_name()) + " " + object_address(pdo.index); };
            const auto report = [&](const std::string& message) {
                context.report(info_or_object(*object), message, {context.note(pdo.pos, pdo_name() + " is declared here")});
            };
            const std::size_t common = std::min(defaults.size(), declared_values.size());
            for (std::size_t k = 0; k < common; ++k) {
                const std::uint64_t declared = declared_values[k];
                if (defaults[k] == declared) continue;
                report("the default of mapping object " + object_address(pdo.index) + " maps " + mapping_text(defaults[k]) + " as entry " +
                       std::to_string(k + 1) + ", but " + pdo_name() + " lists " + mapping_text(declared));
                return;
            }
            if (defaults.size() == declared_values.size()) return;
            report("the default of mapping object " + object_address(pdo.index) + " maps " +
                   std::to_string(defaults.size()) + " entries, but " + pdo_name() + " lists " + std::to_string(declared_values.size()));
        });
    }
}

constexpr Rule pdo_mapping_default{
    .id = "pdo-mapping-default",
    .default_severity = Severity::warning,
    .summary = "A mapping object's default (0x16xx/0x1Axx) differs from the PDO's entries",
    .rationale =
        "The default value of mapping object 0x16xx/0x1Axx sub-index k is the k-th entry of the PDO encoded as "
        "index<<16 | subindex<<8 | bit length (ETG.1000.6; STÖBER ECS 5000 EtherCAT manual §7.1.1 shows the byte "
        "layout). When it disagrees with the ESI entries, a master that reads the mapping from the device and one "
        "that trusts the ESI exchange differently laid out data (leducp/KickCAT synthesises these objects from the "
        "PDOs when a Dictionary lacks them).",
    .bad_example =
        "<RxPdo><Index>#x1600</Index><Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>8</BitLen>… with 0x1600:01 "
        "default #x70000110",
    .good_example =
        "<RxPdo><Index>#x1600</Index><Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>8</BitLen>… with 0x1600:01 "
        "default #x70000108",
    .check = check_mapping_default,
};

}  // namespace

void add_pdo_default(std::vector<Rule>& out) {
    out.insert(out.end(), {
        pdo_assign_default,
        pdo_mapping_default,
    });
}

}  // namespace esi::rules
