// InitCmd values typed by their object: `value: 8` for Modes of operation (SINT) becomes the one
// byte 08, `value: 0x1600` for a UINT entry the bytes 00 16. A value that does not fit is an error
// at its line. The servo manuals show why this matters: their example writes Controlword (16 bit)
// with Data "0", an odd-length, too-short hexBinary (manuals-servo-item-afag §1.8).

#include "derive/steps.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::derive {

void derive_init_values(std::vector<InitCmd>& init_cmds, const std::vector<InitCmdValue>& values, const Dictionary* dictionary,
                        Context& context) {
    for (const InitCmdValue& v : values) {
        if (v.cmd >= init_cmds.size()) continue;
        InitCmd& cmd = init_cmds[v.cmd];
        const std::uint32_t index = cmd.index.value_or(0);
        const std::uint32_t subindex = cmd.subindex.value_or(0);
        const Object* object = dictionary ? dictionary->find_object(index) : nullptr;
        if (!object) {
            context.error(v.value.pos, "derive-init-value",
                          "the InitCmd writes " + hex4(index) + ", which is not in the object dictionary, so its value has no "
                          "type; give the bytes with 'data'");
            continue;
        }
        const ObjectLayout layout = layout_of(dictionary, *object);
        const ObjectEntry* entry = layout.entry(subindex);
        if (!entry) {
            context.error(v.value.pos, "derive-init-value",
                          "the InitCmd writes " + hex4(index) + ":" + std::to_string(subindex) + ", but the object has no sub-index " +
                              std::to_string(subindex));
            continue;
        }
        ValueType type;
        type.basic = entry->basic;
        type.bit_size = entry->bit_size;
        type.name = entry->name + " (" + entry->type + ")";
        const ResolvedType resolved = resolve_type(dictionary, entry->type);
        if (resolved.definition && !resolved.definition->enums.empty()) type.enumeration = resolved.definition;
        const EncodedValue encoded = encode_value(v.value, type);
        if (!encoded.ok()) {
            context.error(v.value.pos, "derive-init-value", "InitCmd value for " + hex4(index) + ":" + std::to_string(subindex) +
                                                                 ": " + encoded.error);
            continue;
        }
        cmd.data = HexData::from_bytes(encoded.bytes);
        cmd.data.pos = v.value.pos;
        cmd.has_data = true;
    }
}

}  // namespace esi::derive
