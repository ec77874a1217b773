#pragma once
// What an index holds: per scope (a Device or Module element), the definitions the features
// point at (objects, DataTypes, PDOs, SyncManagers) with the facts a hover shows, as written in
// the document; and every occurrence of a reference or a definition as a byte range, sorted, so
// that a cursor finds its token by binary search. The front ends (index_xml.cpp,
// index_yaml.cpp) fill it; the features only read it.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "esi/navigate/navigate.hpp"

namespace esi::navigate {

struct Span {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;  // exclusive
    [[nodiscard]] bool empty() const { return begin == end; }
};

// A sub-item of a DataType (a record's member or an array's elements).
struct SubItemDef {
    std::optional<std::uint32_t> subindex;  // SubIdx; absent for an array's "Elements"
    std::string name;
    std::string type;
    std::string bit_size;
    std::string bit_offset;
    std::string access;
    std::string pdo_mapping;
    Span decl;  // its Name
};

struct DataTypeDef {
    std::string name;
    std::string base_type;
    std::string bit_size;
    std::string array;  // "[lower..upper]" of an ARRAY type, else empty
    std::vector<SubItemDef> sub_items;
    Span decl;     // the Name text
    Span element;
};

struct ObjectDef {
    std::uint32_t index = 0;
    std::string name;
    std::string type;
    std::string bit_size;
    std::string access;
    std::string pdo_mapping;
    std::string default_value;
    // Object/Info/SubItem: defaults per sub-item name.
    std::vector<std::pair<std::string, std::string>> sub_defaults;
    // Where the document itself writes a sub-item of this object (a YAML source's `entries` keys);
    // preferred over the DataType's sub-item as a definition.
    std::vector<std::pair<std::uint32_t, Span>> sub_decls;
    Span decl;  // the Index text
    Span element;
};

struct PdoEntryDef {
    std::uint32_t index = 0;
    std::uint32_t subindex = 0;
    std::uint32_t bit_len = 0;
    std::string name;
    Span decl;
    Span element;
};

struct PdoDef {
    bool tx = false;
    std::uint32_t index = 0;
    std::string name;
    std::optional<std::uint32_t> sm;  // Pdo@Sm: assigned to this SM by default
    std::vector<PdoEntryDef> entries;
    Span decl;  // the Index text
    Span element;
    [[nodiscard]] std::uint64_t bit_size() const;
};

struct SmDef {
    std::uint32_t number = 0;  // position among the scope's Sm elements
    std::string role;          // MBoxOut, MBoxIn, Outputs, Inputs
    std::string start_address;
    std::string default_size;
    std::string control_byte;
    std::string enable;
    Span decl;  // the role text, or the tag name when there is none
    Span element;
};

struct Scope {
    bool module = false;
    std::string type;  // Device/Type or Module/Type text
    std::string name;
    Span decl;
    Span element;
    std::vector<ObjectDef> objects;
    std::vector<DataTypeDef> data_types;
    std::vector<PdoDef> pdos;
    std::vector<SmDef> sms;

    [[nodiscard]] const ObjectDef* find_object(std::uint32_t index) const;
    [[nodiscard]] const DataTypeDef* find_data_type(std::string_view name) const;
    [[nodiscard]] const PdoDef* find_pdo(std::uint32_t index) const;
    [[nodiscard]] const SmDef* find_sm(std::uint32_t number) const;
};

enum class Target : std::uint8_t { object, data_type, pdo, sync_manager };

// One token that names a definition: the definition itself or a reference to it.
struct Occurrence {
    Span span;
    Target target = Target::object;
    bool declaration = false;
    std::uint32_t scope = 0;
    std::uint32_t key = 0;               // object or PDO index, SM number
    std::optional<std::uint32_t> sub;    // an object reference's subindex
    // A DataType's name is the token's text (Index::token).
};

// Where the cursor stands for completion: which value it types, in which element.
enum class ValueSlot : std::uint8_t { none, object_index, data_type };

class Index {
public:
    std::string path;
    std::string text;
    LineMap lines{std::string_view{}};  // over `text`, set once text is final
    bool yaml = false;
    std::vector<Scope> scopes;
    std::vector<Occurrence> occurrences;  // sorted by span.begin

    [[nodiscard]] std::string_view token(Span span) const {
        return std::string_view(text).substr(span.begin, span.end - span.begin);
    }
    [[nodiscard]] Range range(Span span) const { return lines.range_of(span.begin, span.end); }
    [[nodiscard]] Location location(Span span) const { return Location{path, range(span)}; }
    // The occurrence whose token holds the offset (its end included: a cursor just after a token
    // is on it); null when none.
    [[nodiscard]] const Occurrence* occurrence_at(std::size_t offset) const;
    // The innermost scope whose element holds the offset.
    [[nodiscard]] std::optional<std::uint32_t> scope_at(std::size_t offset) const;
    // The definition an occurrence names, as its occurrence; null when the scope lacks it.
    [[nodiscard]] std::optional<Span> definition_of(const Occurrence& occurrence) const;
    [[nodiscard]] bool same_target(const Occurrence& a, const Occurrence& b) const;
    void finish();  // sorts the occurrences and builds the line map

private:
    [[nodiscard]] std::optional<Span> find_definition(const Occurrence& occurrence) const;
};

// The front ends. Both leave the index empty when the text is not their format.
void index_xml(Index& index);
void index_yaml(Index& index);

// Completion items for the basic types not in `seen` (completion.cpp).
void add_basic_types(const Range& replace, std::set<std::string_view>& seen, std::vector<CompletionItem>& out);

// An object index from its text ("#x6000", "0x6000", "24576"); nullopt when it is none.
[[nodiscard]] std::optional<std::uint32_t> parse_index_number(std::string_view text);

}  // namespace esi::navigate
