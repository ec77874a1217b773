#pragma once
// Bit-layout pictures: a process image or one PDO drawn as an SVG, bytes as rows and bits as
// columns (bit 0 on the left, so a field that runs on past the end of a byte continues at the
// start of the next row, as offsets count). Every field is a labelled box; padding is hatched;
// bytes no field covers are shaded; a field that straddles byte boundaries without filling
// whole bytes is drawn as its pieces with dashed cut edges. Long names are shortened in the
// box, whole in its title (tooltip and screen readers). Runs of five or more rows inside one
// field, or covered by none, are drawn as one elided band so that large images stay readable.
//
// The input is a plain list, so any layer can draw with it: esi-doc's datasheets and HTML diffs
// (PDOs and SyncManager images) and a master configuration's process-image map (name, bit
// offset, bit size, type of each variable).
//
// Output is one <svg> element for inline use in HTML, deterministic, with presentation
// attributes for its colours (so it reads without a stylesheet) and class names a page's CSS can
// override: svg.bit-layout; g.entry (+ .padding, .straddle, .mark-added/-removed/-moved/
// -resized, .group-N); rect.piece; text.label, text.type; text.offset; path.grid; path.cut.

#include <cstdint>
#include <span>
#include <string>

namespace esi::doc {

// How a field differs from the other side of a diff; none outside diffs.
enum class FieldMark { none, added, removed, moved, resized };

struct LayoutField {
    std::string name;             // shortened in the box, whole in its title
    std::uint64_t bit_offset = 0;  // from the start of the picture
    std::uint64_t bit_size = 0;   // 0: drawn as a thin marker at its offset
    std::string type;             // data type as written ("UINT", "BOOL"); may be empty
    std::string address;          // what the field maps, e.g. "0x6000:01"; may be empty
    bool padding = false;         // a gap entry (PDO entry Index 0): hatched
    std::uint32_t group = 0;      // fields of one group (e.g. one PDO in an SM image) share a tint
    FieldMark mark = FieldMark::none;
};

struct BitLayoutOptions {
    std::string id;              // unique in the page ([A-Za-z0-9_-]); the SVG's id, prefix of its inner ids
    std::string title;           // the picture's accessible name
    std::uint64_t byte_size = 0;  // bytes drawn: at least those the fields cover
};

// The fields may come in any order and may overlap (a broken description); each is drawn where
// its offset says. Offsets and sizes are bounded only by std::uint64_t: elision keeps the
// picture (and the time to draw it) proportional to the number of fields.
[[nodiscard]] std::string render_bit_layout_svg(std::span<const LayoutField> fields, const BitLayoutOptions& options);

// "Status word: 0x6041:00, UINT, 16 bits at byte 2 bit 0": a field's accessible label (the
// title of its box; esi-doc's tables use the same words).
[[nodiscard]] std::string field_description(const LayoutField& field);

}  // namespace esi::doc
