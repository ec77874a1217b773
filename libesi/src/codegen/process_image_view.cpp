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

std::uint64_t native_bits(const std::string& c_type) {
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

bool is_integer_type(const std::string& c_type) { return c_type.find("int") != std::string::npos; }

std::string unsigned_for(std::uint64_t bits) {
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
    explicit ImageBuilder(const ViewContext& context) : context_(context) {}

    void add(const MemberSource& source, std::uint64_t offset, std::uint64_t bits) {
        if (bits == 0) return;
        const CType ct = c_type_of(source.basic, bits);
        const bool aligned = offset % 8 == 0;
        const bool whole = bits % 8 == 0;
        if (aligned && whole) {
            if (!source.padding && ct.array_length == 0 && native_bits(ct.type) == bits) {
                push(source, ct.type, 0, 0, offset, bits);
            } else {
                const std::string element = !source.padding && ct.type == "char" ? "char" : "uint8_t";
                push(source, element, bits / 8, 0, offset, bits);
            }
            return;
        }
        if (bits <= 64) {
            std::string storage = unsigned_for(bits);
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

    Json take_members() { return std::move(members_); }
    bool has_bit_fields() const { return has_bit_fields_; }

private:
    void push(const MemberSource& source, const std::string& c_type, std::uint64_t array_length, std::uint64_t bit_width,
              std::uint64_t offset, std::uint64_t bits) {
        Json m;
        const std::string c_name = source.padding ? scope_.claim("reserved_" + std::to_string(reserved_++))
                                                  : scope_.claim(source.wanted, lower_hex(source.pdo_index));
        m["c_name"] = c_name;
        m["c_type"] = c_type;
        m["c_array_suffix"] = array_length ? "[" + std::to_string(array_length) + "]" : std::string();
        m["is_bit_field"] = bit_width != 0;
        m["bit_width"] = bit_width;
        m["is_padding"] = source.padding;
        m["byte_offset"] = offset / 8;
        m["bit_offset"] = offset;
        m["bit_length"] = bits;
        m["name"] = source.name;
        m["comment"] = c_comment_text(source.name);
        const std::uint32_t index = source.entry ? source.entry->index : 0;
        const std::uint32_t subindex = source.entry ? source.entry->effective_subindex() : 0;
        m["index_hex"] = hex(index, 4);
        m["subindex_hex"] = hex(subindex, 2);
        m["data_type"] = source.basic ? std::string(source.basic->esi_name)
                                      : (source.entry && source.entry->data_type ? *source.entry->data_type : std::string());
        m["pdo_index_hex"] = hex(source.pdo_index, 4);
        if (bit_width) has_bit_fields_ = true;
        members_.push_back(std::move(m));
    }

    const ViewContext& context_;
    IdentifierScope scope_;
    Json members_ = Json::array();
    unsigned reserved_ = 0;
    bool has_bit_fields_ = false;
};

}  // namespace

Json process_image_view(const Device& device, PdoDirection direction, const ViewContext& context) {
    const Dictionary* dictionary = device.dictionary();
    std::vector<const Pdo*> pdos;
    for (const Pdo& pdo : device.pdos(direction))
        if (pdo.sm) pdos.push_back(&pdo);
    std::stable_sort(pdos.begin(), pdos.end(), [](const Pdo* a, const Pdo* b) { return *a->sm < *b->sm; });

    ImageBuilder builder(context);
    Json pdo_list = Json::array();
    Json sms = Json::array();
    std::uint64_t offset = 0;
    for (const Pdo* pdo : pdos) {
        pdo_list.push_back(Json{{"index", pdo->index}, {"index_hex", hex(pdo->index, 4)}, {"sm", *pdo->sm}});
        if (sms.empty() || sms.back().get<std::uint32_t>() != *pdo->sm) sms.push_back(*pdo->sm);
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
    Json image;
    image["present"] = offset > 0;
    image["direction"] = direction == PdoDirection::rx ? "rx" : "tx";
    image["bit_size"] = offset;
    image["byte_size"] = (offset + 7) / 8;
    image["pdos"] = std::move(pdo_list);
    image["sms"] = std::move(sms);
    image["has_bit_fields"] = builder.has_bit_fields();
    image["members"] = builder.take_members();
    return image;
}

}  // namespace esi::codegen
