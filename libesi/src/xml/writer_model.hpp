#pragma once
// Model -> elements: the pieces of the ESI writer shared by its files (writer.cpp for the roots,
// vendor and groups; writer_device.cpp for devices, modules and slots; writer_mailbox.cpp for
// mailboxes and InitCmds; writer_dictionary.cpp for profiles and object dictionaries). Every
// function writes one element in ETG.2000 schema 1.17 order: typed attributes in a fixed order,
// then unknown ones; typed children in schema order with the unknown ones placed by ChildPlacer.

#include <optional>
#include <string_view>
#include <type_traits>

#include "esi/model/device.hpp"
#include "xml/writer_emitter.hpp"
#include "xml/writer_extras.hpp"

namespace esi::xml_writer {

// ---- number formats: one per field family (docs/esi-writer.md, "Numbers") -----------------
// Identities and 32-bit codes: Vendor Id, ProductCode, RevisionNo, SerialNo, ModuleIdent, Slot
// Default/Fallback, ModuleClass VendorId, Flags/Attribute, Info/Unit.
inline NumberText identity_hex(std::uint64_t v) { return NumberText::hex(v, 8); }
// 16-bit indices and addresses: object, data type, PDO, entry, Exclude and InitCmd indices,
// Sm StartAddress, Dc AssignActivate.
inline NumberText index_hex(std::uint64_t v) { return NumberText::hex(v, 4); }
// Sm ControlByte.
inline NumberText byte_hex(std::uint64_t v) { return NumberText::hex(v, 2); }
// Everything else is decimal: sizes, bit lengths and offsets, sub-indices, counts, SM numbers,
// times, Enable, values (Min/Max/Default, Enum), and every field the schema types xs:int.

inline constexpr std::string_view bool_text(bool value) { return value ? "true" : "false"; }

// ---- attributes ---------------------------------------------------------------------------
inline void put_text(XmlEmitter& out, std::string_view name, const std::optional<std::string>& value) {
    if (value) out.attribute(name, *value);
}
inline void put_bool(XmlEmitter& out, std::string_view name, const std::optional<bool>& value) {
    if (value) out.attribute(name, bool_text(*value));
}
template <class T>
void put_decimal(XmlEmitter& out, std::string_view name, T value) {
    if constexpr (std::is_signed_v<T>) out.attribute(name, NumberText::decimal(static_cast<std::int64_t>(value)).view());
    else out.attribute(name, NumberText::decimal(static_cast<std::uint64_t>(value)).view());
}
template <class T>
void put_decimal(XmlEmitter& out, std::string_view name, const std::optional<T>& value) {
    if (value) put_decimal(out, name, *value);
}
inline void put_hex(XmlEmitter& out, std::string_view name, const std::optional<std::uint32_t>& value, NumberText (*format)(std::uint64_t)) {
    if (value) out.attribute(name, format(*value).view());
}

// ---- leaf elements ------------------------------------------------------------------------
template <class T>
void leaf_decimal(XmlEmitter& out, std::string_view name, T value) {
    if constexpr (std::is_same_v<T, Number>) out.leaf(name, NumberText::decimal(value).view());
    else if constexpr (std::is_signed_v<T>) out.leaf(name, NumberText::decimal(static_cast<std::int64_t>(value)).view());
    else out.leaf(name, NumberText::decimal(static_cast<std::uint64_t>(value)).view());
}
// Elements with simple content (Type, Sm, Fmmu, Su, FoE, VoE …): the schema places no children.
inline constexpr ChildOrder no_children{};

// Index elements of PDOs, entries and InitCmds: #x value with the slot-dependency flags.
inline void write_index(XmlEmitter& out, std::uint32_t index, const std::optional<bool>& depend_on_slot,
                        const std::optional<bool>& depend_on_slot_group) {
    out.begin("Index");
    put_bool(out, "DependOnSlot", depend_on_slot);
    put_bool(out, "DependOnSlotGroup", depend_on_slot_group);
    out.text(index_hex(index).view());
    out.end();
}

// xs:hexBinary, with the hex digits in upper case (anything that is not a hex digit is kept as
// it was, so that a broken value stays visibly broken).
void text_hex_data(XmlEmitter& out, const HexData& data);
void leaf_hex_data(XmlEmitter& out, std::string_view name, const HexData& data);
void write_localized(XmlEmitter& out, std::string_view element, const LocalizedText& text);
void write_names(XmlEmitter& out, ChildPlacer& children, std::string_view element, const Names& names);
// Image16x14, ImageFile16x14, ImageData16x14 (the schema allows one; all present are written).
void write_images(XmlEmitter& out, ChildPlacer& children, const Images& images);

// ---- elements (writer_device.cpp) ---------------------------------------------------------
void write_device(XmlEmitter& out, const Device& device);
void write_module(XmlEmitter& out, const Module& module);

// ---- elements (writer_mailbox.cpp) --------------------------------------------------------
void write_mailbox(XmlEmitter& out, const Mailbox& mailbox);

// ---- elements (writer_dictionary.cpp) -----------------------------------------------------
void write_profile(XmlEmitter& out, const Profile& profile);
void write_dictionary(XmlEmitter& out, const Dictionary& dictionary);

}  // namespace esi::xml_writer
