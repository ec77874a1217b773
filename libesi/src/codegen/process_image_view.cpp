// The default process image of one direction as a packed struct: the PDOs a master assigns by
// default (those with an Sm attribute, ETG.2000 PdoType@Sm) laid end to end in SM order, each entry
// at its bit offset. Byte-aligned entries of a native size become plain members; BOOL, BITn and
// entries that do not start on a byte boundary become bit fields; padding entries (Index 0) become
// reserved members, so the struct is exactly the SM's bytes.

#include <algorithm>

#include "codegen/values.hpp"
#include "codegen/view_parts.hpp"
#include "esi/codegen/identifier.hpp"

namespace esi::codegen {

namespace {

std::uint64_t native_bits(std::string_view c_type) {
    if (c_type == "uint8_t" || c_type == "int8_t") return 8;
    if (c_type == "uint16_t" || c_type == "int16_t") return 16;
    if (c_type == "uint32_t" || c_type == "int32_t" || c_type == "float") return 32;
    if (c_type == "uint64_t" || c_type == "int64_t" || c_type == "double") return 64;
    return 0;
}

std::string lower_hex(std::uint32_t value) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%04x", value);
    return buffer;
}

bool is_integer_type(std::string_view c_type) { return c_type.find("int") != std::string_view::npos; }

std::string_view unsigned_for(std::uint64_t bits) {
    return bits <= 8 ? "uint8_t" : bits <= 16 ? "uint16_t" : bits <= 32 ? "uint32_t" : "uint64_t";
}

struct MemberSource {
    std::string name;       // display name
    std::string wanted;     // identifier before de-duplication
    const BasicType* basic = nullptr;
    const PdoEntry* entry = nullptr;
    std::uint32_t pdo_index = 0;
    bool padding = false;
};

class ImageBuilder {
public:
    explicit ImageBuilder(const ViewContext& context) : context_(context), members_(*context.arena) {}

    void add(const MemberSource& source, std::uint64_t offset, std::uint64_t bits) {
        if (bits == 0) return;
        const CType ct = c_type_of(source.basic, bits);
        const bool aligned = offset % 8 == 0;
        const bool whole = bits % 8 == 0;
        if (aligned && whole) {
            if (!source.padding && ct.array_length == 0 && native_bits(ct.type) == bits) {
                push(source, ct.type, 0, 0, offset, bits);
            } else {
                const std::string_view element = !source.padding && ct.type == "char" ? "char" : "uint8_t";
                push(source, element, bits / 8, 0, offset, bits);
            }
            return;
        }
        if (bits <= 64) {
            std::string_view storage = unsigned_for(bits);
            if (!source.padding && ct.array_length == 0 && is_integer_type(ct.type) && native_bits(ct.type) >= bits) storage = ct.type;
            push(source, storage, 0, bits, offset, bits);
            return;
        }
        // Longer than 64 bits and not byte-aligned: no C type holds it, so it is split at the next
        // byte boundary into a bit field and the aligned rest.
        if (!source.padding && source.entry)
            context_.warn("codegen-split-pdo-entry",
                          "PDO entry " + hex(source.entry->index, 4) + ":" + hex(source.entry->effective_subindex(), 2) +
                              " is longer than 64 bits and not byte-aligned; its process-image member is split",
                          source.entry->pos);
        const std::uint64_t head = 8 - offset % 8;
        MemberSource part = source;
        part.basic = nullptr;
        add(part, offset, head);
        add(part, offset + head, bits - head);
    }

    ViewValue take_members() { return members_.finish(); }
    bool has_bit_fields() const { return has_bit_fields_; }

private:
    void push(const MemberSource& source, std::string_view c_type, std::uint64_t array_length, std::uint64_t bit_width,
              std::uint64_t offset, std::uint64_t bits) {
        ViewArena& arena = *context_.arena;
        ObjectBuilder m(arena);
        const std::string c_name = source.padding ? scope_.claim("reserved_" + std::to_string(reserved_++))
                                                  : scope_.claim(source.wanted, lower_hex(source.pdo_index));
        m.add("c_name", c_name);
        m.add("c_type", ViewValue::of_static(c_type));
        m.add("c_array_suffix", array_length ? arena.string("[" + std::to_string(array_length) + "]") : ViewValue::of_static(""));
        m.add("is_bit_field", bit_width != 0);
        m.add("bit_width", bit_width);
        m.add("is_padding", source.padding);
        m.add("byte_offset", offset / 8);
        m.add("bit_offset", offset);
        m.add("bit_length", bits);
        m.add("name", source.name);
        m.add("comment", c_comment_text(source.name));
        const std::uint32_t index = source.entry ? source.entry->index : 0;
        const std::uint32_t subindex = source.entry ? source.entry->effective_subindex() : 0;
        m.add("index_hex", hex_text(index, 4));
        m.add("subindex_hex", hex_text(subindex, 2));
        m.add("data_type", source.basic ? ViewValue::of_static(source.basic->esi_name)
                                        : arena.string(source.entry && source.entry->data_type ? *source.entry->data_type : std::string()));
        m.add("pdo_index_hex", hex_text(source.pdo_index, 4));
        if (bit_width) has_bit_fields_ = true;
        members_.add(m.finish());
    }

    const ViewContext& context_;
    IdentifierScope scope_;
    ListBuilder members_;
    unsigned reserved_ = 0;
    bool has_bit_fields_ = false;
};

}  // namespace

ViewValue process_image_view(const Device& device, PdoDirection direction, const ViewContext& context) {
    ViewArena& arena = *context.arena;
    const Dictionary* dictionary = device.dictionary();
    std::vector<const Pdo*> pdos;
    for (const Pdo& pdo : device.pdos(direction))
        if (pdo.sm) pdos.push_back(&pdo);
    std::stable_sort(pdos.begin(), pdos.end(), [](const Pdo* a, const Pdo* b) { return *a->sm < *b->sm; });

    ImageBuilder builder(context);
    ListBuilder pdo_list(arena);
    std::vector<std::uint32_t> sms;
    std::uint64_t offset = 0;
    for (const Pdo* pdo : pdos) {
        ObjectBuilder p(arena);
        p.add("index", pdo->index);
        p.add("index_hex", hex_text(pdo->index, 4));
        p.add("sm", *pdo->sm);
        pdo_list.add(p.finish());
        if (sms.empty() || sms.back() != *pdo->sm) sms.push_back(*pdo->sm);
        for (const PdoEntry& e : pdo->entries) {
            MemberSource source;
            source.entry = &e;
            source.pdo_index = pdo->index;
            source.padding = e.is_padding();
            if (!source.padding) {
                source.basic = pdo_entry_basic_type(e, dictionary);
                source.name = primary_text(e.names);
                if (source.name.empty() && dictionary)
                    if (const Object* o = dictionary->find_object(e.index)) source.name = primary_text(o->names);
                char fallback[32];
                std::snprintf(fallback, sizeof fallback, "entry_%04X_%02X", e.index, e.effective_subindex());
                source.wanted = c_identifier(source.name, fallback);
            } else {
                source.name = "padding";
            }
            builder.add(source, offset, e.bit_len);
            offset += e.bit_len;
        }
    }
    ObjectBuilder image(arena);
    image.add("present", offset > 0);
    image.add("direction", ViewValue::of_static(direction == PdoDirection::rx ? "rx" : "tx"));
    image.add("bit_size", offset);
    image.add("byte_size", (offset + 7) / 8);
    image.add("pdos", pdo_list.finish());
    ListBuilder sm_list(arena);
    for (const std::uint32_t sm : sms) sm_list.add(sm);
    image.add("sms", sm_list.finish());
    image.add("has_bit_fields", builder.has_bit_fields());
    image.add("members", builder.take_members());
    return image.finish();
}

}  // namespace esi::codegen
