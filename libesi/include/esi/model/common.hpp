#pragma once
// Building blocks shared by every model element: localized names, hex-binary payloads, and
// the verbatim store for XML the model does not cover, so that nothing is dropped silently.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/source_pos.hpp"

namespace esi {

// A <Name LcId="1031">…</Name> (or Comment, URL, Text …). Text is trimmed.
struct LocalizedText {
    std::string text;
    std::optional<std::uint32_t> lcid;
    SourcePos pos;
};
using Names = std::vector<LocalizedText>;

// English (LcId 1033) when present, else the entry without LcId, else the first; "" when empty.
[[nodiscard]] const std::string& primary_text(const Names& names);
[[nodiscard]] const LocalizedText* find_lcid(const Names& names, std::uint32_t lcid);

// An xs:hexBinary value. `text` is the value with all whitespace removed, as written otherwise,
// so lint rules can still see odd lengths or bad digits.
struct HexData {
    std::string text;
    SourcePos pos;

    [[nodiscard]] bool valid() const;  // even number of hex digits
    // Decoded bytes in written order; nullopt when not valid.
    [[nodiscard]] std::optional<std::vector<std::uint8_t>> bytes() const;
    [[nodiscard]] std::size_t byte_length() const { return text.size() / 2; }
    [[nodiscard]] static HexData from_bytes(const std::vector<std::uint8_t>& bytes);
};

struct XmlAttribute {
    std::string name;
    std::string value;
    friend bool operator==(const XmlAttribute&, const XmlAttribute&) = default;
};

// An element the model does not cover, kept verbatim (comments and processing instructions
// are not kept). `after` names the element that preceded it in the source so that writers can
// put it back where it was; empty when it was the first child.
struct XmlElement {
    std::string name;
    std::vector<XmlAttribute> attributes;
    std::string text;  // character data directly inside, as written (not trimmed)
    std::vector<XmlElement> children;
    std::string after;
    SourcePos pos;

    [[nodiscard]] const XmlAttribute* attribute(std::string_view attribute_name) const;
    [[nodiscard]] const XmlElement* child(std::string_view child_name) const;
    // Follows a '/'-separated path of child names ("Electrical/EBusCurrent").
    [[nodiscard]] const XmlElement* find(std::string_view path) const;
};

// Structural equality that ignores positions and surrounding whitespace in text.
[[nodiscard]] bool same_content(const XmlElement& a, const XmlElement& b);

// What an element carries beyond the model's typed fields.
struct Extras {
    std::vector<XmlAttribute> attributes;
    std::vector<XmlElement> elements;

    [[nodiscard]] bool empty() const { return attributes.empty() && elements.empty(); }
    [[nodiscard]] const XmlAttribute* attribute(std::string_view name) const;
    [[nodiscard]] const XmlElement* element(std::string_view name) const;
    // First element along a '/'-separated path starting at these extras ("Info/Electrical/EBusCurrent").
    [[nodiscard]] const XmlElement* find(std::string_view path) const;
};

// ImageData16x14 / Image16x14 / ImageFile16x14 as Vendor, Group, Device, Module and Slot carry them.
struct Images {
    std::optional<std::string> image16x14;  // deprecated file reference
    std::optional<std::string> image_file16x14;
    std::optional<HexData> image_data16x14;
    SourcePos image16x14_pos;  // where the deprecated Image16x14 element was written
    [[nodiscard]] bool empty() const { return !image16x14 && !image_file16x14 && !image_data16x14; }
};

}  // namespace esi
