// The object-dictionary part of the view: every object and sub-entry with its type, size, access,
// PDO mappability and values, ready for the C++ header, the C tables and the SOES object list.

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "codegen/values.hpp"
#include "codegen/view_parts.hpp"
#include "esi/codegen/identifier.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::codegen {

namespace {

// ETG.1000.6 SDO Information, entry description: the ObjectAccess bits. SOES uses the same
// bits for its ATYPE_* flags (soes/esc_coe.h).
constexpr unsigned read_preop = 0x01;
constexpr unsigned read_safeop = 0x02;
constexpr unsigned read_op = 0x04;
constexpr unsigned write_preop = 0x08;
constexpr unsigned write_safeop = 0x10;
constexpr unsigned write_op = 0x20;
constexpr unsigned rx_mappable_bit = 0x40;
constexpr unsigned tx_mappable_bit = 0x80;
constexpr unsigned backup_bit = 0x100;
constexpr unsigned setting_bit = 0x200;

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

// ETG.2000 AccessType@ReadRestrictions/@WriteRestrictions: "PreOP", "SafeOP", "OP" joined by '_'
// ("PreOP_SafeOP"). Absent or unrecognised means every state.
unsigned state_bits(const std::optional<std::string>& restrictions, unsigned preop, unsigned safeop, unsigned op) {
    if (!restrictions) return preop | safeop | op;
    unsigned bits = 0;
    const std::string text = lower(*restrictions);
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find('_', start), text.size());
        const std::string token(trim(std::string_view(text).substr(start, end - start)));
        if (token == "preop") bits |= preop;
        else if (token == "safeop") bits |= safeop;
        else if (token == "op") bits |= op;
        start = end + 1;
    }
    return bits ? bits : preop | safeop | op;
}

struct Access {
    std::string_view text = "ro";  // an absent Access element reads as ro
    unsigned word = 0;
    bool readable = true;
    bool writable = false;
    bool rx = false;
    bool tx = false;
    std::string_view pdo_mapping;  // "", "R", "T" or "RT"
};

Access access_of(const ObjectFlags* flags) {
    Access a;
    if (flags && flags->access) {
        const std::string t = lower(trim(*flags->access));
        if (t == "rw") a.text = "rw";
        else if (t == "wo") a.text = "wo";
    }
    a.readable = a.text != "wo";
    a.writable = a.text != "ro";
    if (a.readable)
        a.word |= state_bits(flags ? flags->access_read_restrictions : std::nullopt, read_preop, read_safeop, read_op);
    if (a.writable)
        a.word |= state_bits(flags ? flags->access_write_restrictions : std::nullopt, write_preop, write_safeop, write_op);
    if (flags && flags->pdo_mapping) {
        const std::string m = lower(trim(*flags->pdo_mapping));
        a.rx = m.find('r') != std::string::npos;
        a.tx = m.find('t') != std::string::npos;
        a.pdo_mapping = a.rx && a.tx ? "RT" : a.rx ? "R" : a.tx ? "T" : "";
    }
    if (a.rx) a.word |= rx_mappable_bit;
    if (a.tx) a.word |= tx_mappable_bit;
    if (flags && flags->backup.value_or(0) != 0) a.word |= backup_bit;
    if (flags && flags->setting.value_or(0) != 0) a.word |= setting_bit;
    return a;
}

}  // namespace

EntryAccess entry_access(const ObjectFlags* flags) {
    const Access a = access_of(flags);
    return {a.writable, a.rx, a.tx};
}

namespace {

// SOES names its access combinations (soes/esc_coe.h); anything else is spelled bit by bit.
std::string soes_access(unsigned word) {
    std::string out;
    switch (word & 0x3Fu) {
        case 0x07: out = "ATYPE_RO"; break;
        case 0x38: out = "ATYPE_WO"; break;
        case 0x3F: out = "ATYPE_RW"; break;
        case 0x0F: out = "ATYPE_RWpre"; break;
        case 0x27: out = "ATYPE_RWop"; break;
        case 0x1F: out = "ATYPE_RWpre_safe"; break;
        default: {
            constexpr std::pair<unsigned, const char*> names[] = {{read_preop, "ATYPE_Rpre"},   {read_safeop, "ATYPE_Rsafe"},
                                                                  {read_op, "ATYPE_Rop"},       {write_preop, "ATYPE_Wpre"},
                                                                  {write_safeop, "ATYPE_Wsafe"}, {write_op, "ATYPE_Wop"}};
            for (const auto& [bit, name] : names)
                if (word & bit) out += (out.empty() ? "" : " | ") + std::string(name);
            if (out.empty()) out = "0";
        }
    }
    if (word & rx_mappable_bit) out += " | ATYPE_RXPDO";
    if (word & tx_mappable_bit) out += " | ATYPE_TXPDO";
    if (word & backup_bit) out += " | ATYPE_BACKUP";
    if (word & setting_bit) out += " | ATYPE_SETTING";
    return out;
}

// The DTYPE_* constant SOES defines for a CoE data type. BYTE/WORD/DWORD are given as the unsigned
// type of the same size because SOES's value and PDO handling (COE_setValue, COE_pdoPack) only
// switch over the codes it defines; other codes are given as numbers.
ViewValue soes_datatype(const BasicType* basic, ViewArena& arena) {
    const auto name = [](std::string_view text) { return ViewValue::of_static(text); };
    if (!basic) return name("DTYPE_OCTET_STRING");
    switch (basic->coe_code) {
        case 0x0001: return name("DTYPE_BOOLEAN");
        case 0x0002: return name("DTYPE_INTEGER8");
        case 0x0003: return name("DTYPE_INTEGER16");
        case 0x0004: return name("DTYPE_INTEGER32");
        case 0x0005: case 0x001E: return name("DTYPE_UNSIGNED8");
        case 0x0006: case 0x001F: return name("DTYPE_UNSIGNED16");
        case 0x0007: case 0x0020: return name("DTYPE_UNSIGNED32");
        case 0x0008: return name("DTYPE_REAL32");
        case 0x0009: return name("DTYPE_VISIBLE_STRING");
        case 0x000A: return name("DTYPE_OCTET_STRING");
        case 0x000B: return name("DTYPE_UNICODE_STRING");
        case 0x0010: return name("DTYPE_INTEGER24");
        case 0x0011: return name("DTYPE_REAL64");
        case 0x0015: return name("DTYPE_INTEGER64");
        case 0x0016: return name("DTYPE_UNSIGNED24");
        case 0x001B: return name("DTYPE_UNSIGNED64");
        case 0x002D: return name("DTYPE_BITARR8");
        case 0x002E: return name("DTYPE_BITARR16");
        case 0x002F: return name("DTYPE_BITARR32");
        default: break;
    }
    if (basic->coe_code >= 0x0030 && basic->coe_code <= 0x0037) return arena.string("DTYPE_BIT" + std::to_string(basic->coe_code - 0x002F));
    return arena.string(hex_text(basic->coe_code, 4));
}

}  // namespace

CType c_type_of(const BasicType* basic, std::uint64_t bit_size) {
    const std::uint64_t bytes = (bit_size + 7) / 8;
    auto width = [](std::uint64_t bits, bool is_signed) -> std::string_view {
        static constexpr std::string_view names[2][4] = {{"uint8_t", "uint16_t", "uint32_t", "uint64_t"},
                                                         {"int8_t", "int16_t", "int32_t", "int64_t"}};
        const int w = bits <= 8 ? 0 : bits <= 16 ? 1 : bits <= 32 ? 2 : 3;
        return names[is_signed ? 1 : 0][w];
    };
    if (!basic) return {"uint8_t", std::max<std::uint64_t>(bytes, 1)};
    switch (basic->type_class) {
        case TypeClass::boolean:
        case TypeClass::bit:
        case TypeClass::unsigned_integer:
        case TypeClass::bit_string:
            if (bit_size == 0 || bit_size > 64) break;
            return {width(bit_size, false), 0};
        case TypeClass::signed_integer:
            if (bit_size == 0 || bit_size > 64) break;
            return {width(bit_size, true), 0};
        case TypeClass::real:
            return {bit_size == 64 ? "double" : "float", 0};
        case TypeClass::visible_string:
            return {"char", std::max<std::uint64_t>(bytes, 1)};
        default: break;
    }
    return {"uint8_t", std::max<std::uint64_t>(bytes, 1)};
}

namespace {

std::string_view value_class_name(const BasicType* basic) {
    if (!basic) return "other";
    switch (basic->type_class) {
        case TypeClass::boolean: return "boolean";
        case TypeClass::bit: return "bit";
        case TypeClass::signed_integer: return "signed";
        case TypeClass::unsigned_integer: return "unsigned";
        case TypeClass::real: return "real";
        case TypeClass::bit_string: return "bit_string";
        case TypeClass::visible_string: return "string";
        case TypeClass::octet_string: return "octet_string";
        case TypeClass::unicode_string: return "unicode_string";
        default: return "other";
    }
}

// A name that does not resolve is often a common non-standard spelling ("UINT16").
const BasicType* basic_of(const ObjectEntry& entry) {
    if (entry.basic) return entry.basic;
    const std::string_view standard = standard_type_name_for(trim(entry.type));
    return standard.empty() ? nullptr : find_basic_type(standard);
}

struct EntryInput {
    ObjectEntry entry;
    bool synthesized = false;
    bool mapped = false;  // some RxPdo/TxPdo entry of the device maps it
    bool pdo_configuration = false;  // of a PDO mapping (0x1600-0x17FF, 0x1A00-0x1BFF) or assignment (0x1C10-0x1C2F) object
};

bool is_pdo_configuration(std::uint32_t index) {
    return (index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF) || (index >= 0x1C10 && index <= 0x1C2F);
}

// SOES's access for an entry. A master changes PDO mapping and assignment in PreOp only
// (ETG.1000.6; the servo manual §6.1.1: "im Zustand Pre-Operational"), and SOES reads them only on
// PreOp->SafeOp (esc.c sizeOfPDO): a write in SafeOp or Op would leave the process image and the
// objects disagreeing. Their write access is therefore PreOp only, as in SOES's own dynamic-PDO
// example (applications/rtl_xmc4_dynpdo: ATYPE_RWpre).
unsigned soes_access_word(unsigned word, bool pdo_configuration) {
    if (!pdo_configuration || (word & (write_preop | write_safeop | write_op)) == 0) return word;
    return (word & ~(write_safeop | write_op)) | write_preop;
}

// `object_member` is the object's member in SOES's Obj (empty for a VAR, whose single entry is the
// member itself and carries the object's C name, `var_c_name`). Returns whether the entry lives in
// SOES's Obj.
bool add_entry_view(ListBuilder& list, const EntryInput& input, ObjectCode code, std::uint64_t max_subindex, const std::string& object_member,
                    const std::string& var_c_name, IdentifierScope& scope, std::size_t position) {
    ViewArena& arena = list.arena();
    const ObjectEntry& e = input.entry;
    const BasicType* basic = basic_of(e);
    const Access access = access_of(e.flags);
    EntryValues values = decode_entry_values(e);
    if (code != ObjectCode::var && e.subindex == 0 && values.default_value.kind == DecodedValue::Kind::none && basic &&
        basic->coe_code == 0x0005) {
        // ETG.1000.6: sub-index 0 of an ARRAY or RECORD, UNSIGNED8, holds the highest sub-index;
        // a sub-index 0 of another type is data (STÖBER A261.0, a UDINT error code).
        values.default_value.kind = DecodedValue::Kind::unsigned_integer;
        values.default_value.bits = max_subindex;
        values.default_value.i = static_cast<std::int64_t>(max_subindex);
    }
    const std::string name = e.name.empty() ? "SubIndex " + std::to_string(e.subindex) : e.name;
    const ShortText sub_hex2 = plain_hex_text(e.subindex, 2);
    const std::string c_name = code == ObjectCode::var
                                   ? var_c_name
                                   : scope.claim(c_identifier(name, "subindex_" + sub_hex2.str()), std::string_view(sub_hex2));
    const CType ct = c_type_of(basic, e.bit_size);
    const std::string_view type_name = trim(e.type);

    ObjectBuilder j(arena);
    j.add("position", position);
    j.add("subindex", e.subindex);
    j.add("subindex_hex", hex_text(e.subindex, 2));
    j.add("subindex_hex2", sub_hex2);
    j.add("name", name);
    j.add("c_name", c_name);
    j.add("name_literal", c_string_literal(name));
    j.add("comment", c_comment_text(name));
    j.add("synthesized", input.synthesized);
    const std::string_view data_type = basic ? basic->esi_name : type_name;
    j.add("data_type", basic ? ViewValue::of_static(data_type) : arena.string(data_type));
    j.add("data_type_literal", c_string_literal(data_type));
    j.add("type_name", type_name);
    j.add("coe_name", ViewValue::of_static(basic ? basic->coe_name : std::string_view()));
    j.add("coe_code", basic ? basic->coe_code : 0);
    j.add("coe_code_hex", hex_text(basic ? basic->coe_code : 0, 4));
    j.add("value_class", ViewValue::of_static(value_class_name(basic)));
    j.add("bit_length", e.bit_size);
    j.add("bit_offset", e.bit_offset);
    j.add("byte_length", (e.bit_size + 7) / 8);
    j.add("c_type", ViewValue::of_static(ct.type));
    j.add("is_c_array", ct.array_length != 0);
    j.add("c_array_length", ct.array_length);
    j.add("c_array_suffix", ct.array_length ? arena.string("[" + std::to_string(ct.array_length) + "]") : ViewValue::of_static(""));
    j.add("access", ViewValue::of_static(access.text));
    j.add("readable", access.readable);
    j.add("writable", access.writable);
    j.add("read_restrictions", e.flags && e.flags->access_read_restrictions ? arena.string(*e.flags->access_read_restrictions) : ViewValue::of_static(""));
    j.add("write_restrictions", e.flags && e.flags->access_write_restrictions ? arena.string(*e.flags->access_write_restrictions) : ViewValue::of_static(""));
    j.add("access_word", access.word);
    j.add("access_word_hex", hex_text(access.word, 4));
    j.add("pdo_mapping", ViewValue::of_static(access.pdo_mapping));
    j.add("rx_mappable", access.rx);
    j.add("tx_mappable", access.tx);
    j.add("pdo_mappable", access.rx || access.tx);
    j.add("mapped_in_pdo", input.mapped);
    j.add("default", value_view(arena, values.default_value, e.bit_size));
    j.add("min", value_view(arena, values.min, e.bit_size));
    j.add("max", value_view(arena, values.max, e.bit_size));

    // SOES (soes/esc_coe.h _objd): entries that the master may write or that travel in a PDO live in
    // the application's `Obj` structure (utypes.h); the others are constants in the object list.
    const bool is_text = ct.type == "char" || (ct.array_length != 0);
    const bool count_entry = code != ObjectCode::var && e.subindex == 0;
    // Mapped entries need a variable even when the file forgot their PdoMapping flag.
    const bool stored = access.writable || ((access.rx || access.tx || input.mapped) && !count_entry);
    const std::string member = object_member.empty() ? c_name : object_member + "." + c_name;
    ObjectBuilder soes(arena);
    soes.add("datatype", soes_datatype(basic, arena));
    soes.add("access", soes_access(soes_access_word(access.word, input.pdo_configuration)));
    soes.add("stored", stored);
    soes.add("member", stored ? arena.string(member) : ViewValue::of_static(""));
    ViewValue data = ViewValue::of_static("NULL");
    if (stored) data = arena.string((is_text ? "Obj." : "&Obj.") + member);
    else if (is_text && values.default_value.kind != DecodedValue::Kind::none)
        data = arena.string(c_string_literal(values.default_value.text));
    soes.add("data", data);
    const bool numeric_default = !is_text && values.default_value.kind != DecodedValue::Kind::none;
    // SOES keeps defaults in a 32-bit field (and zero-extends it into 64-bit variables), so a
    // default that does not fit is given as 0 and flagged for the application to set.
    const bool fits = numeric_default && fits_32_bits(values.default_value);
    soes.add("value", fits ? arena.string(bits32_hex(values.default_value, e.bit_size)) : ViewValue::of_static("0"));
    soes.add("value_truncated", numeric_default && !fits);
    j.add("soes", soes.finish());
    list.add(j.finish());
    return stored;
}

}  // namespace

ObjectsView objects_view(const Device& device, const ViewContext& context) {
    ObjectsView out;
    ViewArena& arena = *context.arena;
    const Dictionary* dictionary = device.dictionary();
    if (!dictionary) {
        out.objects = ListBuilder(arena).finish();
        return out;
    }

    std::vector<const Object*> objects;
    objects.reserve(dictionary->objects.size());
    for (const auto& o : dictionary->objects) {
        if (o.index > 0xFFFF) {
            context.warn("codegen-object-skipped", "object index " + hex(o.index, 4) + " is beyond 0xFFFF; not generated", o.index_pos);
            continue;
        }
        objects.push_back(&o);
    }
    std::stable_sort(objects.begin(), objects.end(), [](const Object* a, const Object* b) { return a->index < b->index; });

    std::set<std::pair<std::uint32_t, std::uint32_t>> mapped;
    for (const auto* pdos : {&device.rx_pdos, &device.tx_pdos})
        for (const Pdo& pdo : *pdos)
            for (const PdoEntry& e : pdo.entries)
                if (!e.is_padding()) mapped.emplace(e.index, e.effective_subindex());

    // Names are handed out to application objects (0x2000 and up) first: a device's data object
    // keeps its plain name when a mapping object (0x16xx/0x1Axx) is called the same.
    std::vector<std::size_t> naming_order(objects.size());
    for (std::size_t k = 0; k < objects.size(); ++k) naming_order[k] = k;
    std::stable_partition(naming_order.begin(), naming_order.end(), [&](std::size_t k) { return objects[k]->index >= 0x2000; });
    std::vector<std::string> object_names(objects.size());
    IdentifierScope object_scope;
    for (const std::size_t k : naming_order) {
        const Object& object = *objects[k];
        if (k > 0 && objects[k - 1]->index == object.index) continue;  // a duplicate, skipped below
        const ShortText index_hex4 = plain_hex_text(object.index, 4);
        object_names[k] = object_scope.claim(c_identifier(primary_text(object.names), "object_" + index_hex4.str()), lower(index_hex4));
    }

    ListBuilder object_list(arena);
    std::vector<EntryInput> entries;
    std::size_t position = 0;
    for (std::size_t k = 0; k < objects.size(); ++k) {
        const Object& object = *objects[k];
        if (k > 0 && objects[k - 1]->index == object.index) {
            context.warn("codegen-duplicate-object", "object " + hex(object.index, 4) + " is defined twice; the first definition is generated", object.pos);
            continue;
        }
        ObjectLayout layout = layout_of(dictionary, object);

        entries.clear();
        entries.reserve(layout.entries.size() + 1);
        for (auto& e : layout.entries) {
            if (e.subindex > 255) continue;
            const bool is_mapped = mapped.count({object.index, e.subindex}) != 0;
            entries.push_back({std::move(e), false, is_mapped, is_pdo_configuration(object.index)});
        }
        std::stable_sort(entries.begin(), entries.end(), [](const EntryInput& a, const EntryInput& b) { return a.entry.subindex < b.entry.subindex; });
        for (std::size_t m = 1; m < entries.size();) {
            if (entries[m].entry.subindex == entries[m - 1].entry.subindex) {
                context.warn("codegen-duplicate-subindex",
                             "object " + hex(object.index, 4) + " has sub-index " + std::to_string(entries[m].entry.subindex) + " twice; the first is generated",
                             object.pos);
                entries.erase(entries.begin() + static_cast<std::ptrdiff_t>(m));
            } else {
                ++m;
            }
        }
        std::uint64_t max_subindex = entries.empty() ? 0 : entries.back().entry.subindex;
        if (layout.code != ObjectCode::var && (entries.empty() || entries.front().entry.subindex != 0)) {
            // Every ARRAY/RECORD answers sub-index 0 (ETG.1000.6); add it when the type lacks it.
            EntryInput count;
            count.synthesized = true;
            count.pdo_configuration = is_pdo_configuration(object.index);
            count.entry.subindex = 0;
            count.entry.name = "SubIndex 000";
            count.entry.type = "USINT";
            count.entry.basic = find_basic_type("USINT");
            count.entry.bit_size = 8;
            count.entry.flags = object.flags ? &*object.flags : nullptr;
            entries.insert(entries.begin(), std::move(count));
        }

        const std::string name = primary_text(object.names);
        const std::string& c_name = object_names[k];

        ObjectBuilder o(arena);
        o.add("index", object.index);
        o.add("index_hex", hex_text(object.index, 4));
        o.add("index_hex4", plain_hex_text(object.index, 4));
        o.add("name", name);
        o.add("c_name", c_name);
        o.add("name_literal", c_string_literal(name));
        o.add("comment", c_comment_text(name));
        o.add("object_code", ViewValue::of_static(to_string(layout.code)));
        o.add("object_code_value", layout.code == ObjectCode::var ? 7 : layout.code == ObjectCode::array ? 8 : 9);
        o.add("is_var", layout.code == ObjectCode::var);
        o.add("is_array", layout.code == ObjectCode::array);
        o.add("is_record", layout.code == ObjectCode::record);
        o.add("type_name", trim(object.type));
        o.add("bit_size", object.bit_size);
        o.add("category", object.flags && object.flags->category ? arena.string(*object.flags->category) : ViewValue::of_static(""));
        o.add("max_subindex", layout.code == ObjectCode::var ? 0 : max_subindex);
        o.add("first_entry", position);
        o.add("entry_count", entries.size());

        IdentifierScope entry_scope;
        const std::string member = layout.code == ObjectCode::var ? std::string() : c_name;
        ListBuilder list(arena);
        bool stored = false;
        for (const auto& input : entries) {
            stored = add_entry_view(list, input, layout.code, max_subindex, member, c_name, entry_scope, position) || stored;
            ++position;
        }
        {
            ObjectBuilder soes(arena);
            soes.add("stored", stored);
            o.add("soes", soes.finish());
        }
        o.add("entries", list.finish());
        object_list.add(o.finish());
        out.soes_storage = out.soes_storage || stored;
    }
    out.objects = object_list.finish();
    out.entry_count = position;
    return out;
}

}  // namespace esi::codegen
