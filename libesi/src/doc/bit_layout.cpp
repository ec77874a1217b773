// Drawing a bit layout (see esi/doc/bit_layout.hpp for what the picture shows).
//
// Geometry: a column per bit (bit 0 left), a row per byte, an offset label column on the left.
// A field becomes pieces: the part in its first byte, the whole bytes in between (one rectangle),
// the part in its last byte. Rows are mapped to vertical slots; an elided band (a run of rows
// inside one field's rectangle, or covered by no field) takes one slot. All coordinates are
// integers, so the output is the same on every machine.

#include "esi/doc/bit_layout.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <string_view>
#include <vector>

#include "doc/markup.hpp"

namespace esi::doc {

namespace {

constexpr int label_width = 56;
constexpr int column_width = 80;
constexpr int grid_width = 8 * column_width;
constexpr int picture_width = label_width + grid_width + 8;
constexpr int head_height = 20;
constexpr int row_height = 26;
constexpr int bottom_margin = 6;
// Average advance of the monospace font at 11 px, rounded up so that shortened names fit.
constexpr double char_width = 6.7;
// A run of this many rows (inside one field, or covered by none) or more is elided.
constexpr std::uint64_t elide_from = 5;

struct Tint {
    std::string_view fill;
    std::string_view stroke;
};
constexpr std::array group_tints{Tint{"#dbeafe", "#60a5fa"}, Tint{"#dcfce7", "#4ade80"}, Tint{"#fef3c7", "#f59e0b"},
                                 Tint{"#f3e8ff", "#c084fc"}, Tint{"#ffe4e6", "#fb7185"}, Tint{"#e0f2fe", "#38bdf8"}};

struct MarkStyle {
    std::string_view css;    // class suffix
    std::string_view badge;  // drawn in the box's corner: the mark is not told by colour alone
    std::string_view words;  // in the title
    Tint tint;
};
MarkStyle mark_style(FieldMark mark) {
    switch (mark) {
        case FieldMark::added: return {"added", "+", "added", {"#bbf7d0", "#15803d"}};
        case FieldMark::removed: return {"removed", "−", "removed", {"#fecaca", "#b91c1c"}};
        case FieldMark::moved: return {"moved", "↔", "moved", {"#bfdbfe", "#1d4ed8"}};
        case FieldMark::resized: return {"resized", "±", "resized", {"#fde68a", "#b45309"}};
        case FieldMark::none: break;
    }
    return {};
}

std::uint64_t saturating_end(const LayoutField& f) {
    return f.bit_offset > std::numeric_limits<std::uint64_t>::max() - f.bit_size ? std::numeric_limits<std::uint64_t>::max()
                                                                                 : f.bit_offset + f.bit_size;
}

// Part of a field in one row (first_row == last_row) or in whole rows (columns 0..8).
struct Piece {
    std::size_t field = 0;
    std::uint64_t first_row = 0;
    std::uint64_t last_row = 0;
    int first_column = 0;
    int end_column = 8;  // exclusive
    [[nodiscard]] bool whole_rows() const { return first_column == 0 && end_column == 8; }
};

void split(const LayoutField& f, std::size_t index, std::vector<Piece>& out) {
    const std::uint64_t start = f.bit_offset;
    const std::uint64_t end = saturating_end(f);
    const std::uint64_t first_row = start / 8;
    const std::uint64_t last_row = (end - 1) / 8;
    const int start_column = static_cast<int>(start % 8);
    const int end_column = static_cast<int>((end - 1) % 8) + 1;
    if (first_row == last_row) {
        out.push_back({index, first_row, first_row, start_column, end_column});
        return;
    }
    std::uint64_t whole_from = first_row;
    std::uint64_t whole_to = last_row;
    if (start_column != 0) {
        out.push_back({index, first_row, first_row, start_column, 8});
        ++whole_from;
    }
    const bool tail = end_column != 8;
    if (tail) --whole_to;
    if (whole_from <= whole_to) out.push_back({index, whole_from, whole_to, 0, 8});
    if (tail) out.push_back({index, last_row, last_row, 0, end_column});
}

struct Band {
    std::uint64_t first = 0;  // rows first..last are drawn as one slot
    std::uint64_t last = 0;
};

// Bands from a sweep over the pieces' row ranges: rows covered by exactly one whole-rows piece
// (keeping its first two rows and its last row visible, so the box shows its start, its end and
// room for its label), and rows covered by nothing (keeping the first and last).
std::vector<Band> elided_bands(const std::vector<Piece>& pieces, std::uint64_t row_count) {
    struct Event {
        std::uint64_t row;
        bool opens;
        std::size_t piece;
    };
    std::vector<Event> events;
    events.reserve(pieces.size() * 2);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        events.push_back({pieces[i].first_row, true, i});
        events.push_back({pieces[i].last_row + 1, false, i});
    }
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
        if (a.row != b.row) return a.row < b.row;
        if (a.opens != b.opens) return !a.opens;  // close before open at the same row
        return a.piece < b.piece;
    });
    std::vector<Band> bands;
    const auto add = [&](std::uint64_t first, std::uint64_t last) {
        if (last >= first && last - first + 1 >= 2) bands.push_back({first, last});
    };
    std::set<std::size_t> active;
    std::uint64_t row = 0;  // start of the current run of rows with the same active pieces
    std::size_t e = 0;
    while (row < row_count) {
        const std::uint64_t next = e < events.size() ? std::min(events[e].row, row_count) : row_count;
        if (next > row) {
            if (active.empty() && next - row >= elide_from) {
                add(row + 1, next - 2);
            } else if (active.size() == 1) {
                const Piece& p = pieces[*active.begin()];
                if (p.whole_rows() && p.last_row - p.first_row + 1 >= elide_from)
                    add(std::max(row, p.first_row + 2), std::min(next - 1, p.last_row - 1));
            }
            row = next;
        }
        for (; e < events.size() && events[e].row == row; ++e) {
            if (events[e].opens)
                active.insert(events[e].piece);
            else
                active.erase(events[e].piece);
        }
        if (e == events.size() && next == row_count) break;
    }
    return bands;
}

// Row -> vertical slot, with each band taking one slot.
class RowMap {
public:
    explicit RowMap(std::vector<Band> bands) : bands_(std::move(bands)) {
        std::uint64_t saved = 0;
        for (const Band& b : bands_) {
            saved_before_.push_back(saved);
            saved += b.last - b.first;
        }
    }
    [[nodiscard]] std::uint64_t slot(std::uint64_t row) const {
        // The last band that starts at or before `row`.
        const auto it = std::upper_bound(bands_.begin(), bands_.end(), row, [](std::uint64_t r, const Band& b) { return r < b.first; });
        if (it == bands_.begin()) return row;
        const std::size_t k = static_cast<std::size_t>(it - bands_.begin()) - 1;
        const Band& b = bands_[k];
        if (row <= b.last) return b.first - saved_before_[k];
        return row - saved_before_[k] - (b.last - b.first);
    }
    [[nodiscard]] const std::vector<Band>& bands() const { return bands_; }

private:
    std::vector<Band> bands_;
    std::vector<std::uint64_t> saved_before_;
};

long long top_of(const RowMap& map, std::uint64_t row) { return head_height + static_cast<long long>(map.slot(row)) * row_height; }

void put(std::string& out, long long v) { out += std::to_string(v); }

void text_element(std::string& out, std::string_view css, long long x, long long y, std::string_view anchor, std::string_view text) {
    out += "<text class=\"";
    out += css;
    out += "\" x=\"";
    put(out, x);
    out += "\" y=\"";
    put(out, y);
    out += "\" text-anchor=\"";
    out += anchor;
    out += "\">";
    append_escaped(out, text);
    out += "</text>";
}

std::string plural_bits(std::uint64_t n) { return std::to_string(n) + (n == 1 ? " bit" : " bits"); }

}  // namespace

std::string field_description(const LayoutField& field) {
    std::string out = field.padding ? (field.name.empty() ? std::string("padding") : field.name + " (padding)") : field.name;
    if (out.empty()) out = "unnamed";
    out += ":";
    if (!field.address.empty()) out += " " + field.address + ",";
    if (!field.type.empty()) out += " " + field.type + ",";
    out += " " + plural_bits(field.bit_size) + " at byte " + std::to_string(field.bit_offset / 8) + " bit " +
           std::to_string(field.bit_offset % 8);
    if (field.bit_size > 0) {
        const std::uint64_t last_byte = (saturating_end(field) - 1) / 8;
        const bool whole_bytes = field.bit_offset % 8 == 0 && field.bit_size % 8 == 0;
        if (last_byte != field.bit_offset / 8 && !whole_bytes)
            out += ", straddles bytes " + std::to_string(field.bit_offset / 8) + "–" + std::to_string(last_byte);
    }
    if (field.mark != FieldMark::none) out += " (" + std::string(mark_style(field.mark).words) + ")";
    return out;
}

std::string render_bit_layout_svg(std::span<const LayoutField> fields, const BitLayoutOptions& options) {
    std::vector<Piece> pieces;
    pieces.reserve(fields.size() * 2);
    std::uint64_t byte_count = options.byte_size;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const LayoutField& f = fields[i];
        if (f.bit_size == 0) {
            byte_count = std::max(byte_count, f.bit_offset / 8 + 1);
            continue;
        }
        split(f, i, pieces);
        byte_count = std::max(byte_count, (saturating_end(f) - 1) / 8 + 1);
    }
    const RowMap rows(elided_bands(pieces, byte_count));
    const std::uint64_t slot_count = byte_count == 0 ? 1 : rows.slot(byte_count - 1) + 1;
    const long long grid_height = static_cast<long long>(slot_count) * row_height;
    const long long height = head_height + grid_height + bottom_margin;
    const std::string& id = options.id;

    std::string out;
    out.reserve(2048 + fields.size() * 420);
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"bit-layout\" id=\"";
    append_escaped(out, id);
    out += "\" width=\"";
    put(out, picture_width);
    out += "\" height=\"";
    put(out, height);
    out += "\" viewBox=\"0 0 ";
    put(out, picture_width);
    out += " ";
    put(out, height);
    out += "\" role=\"group\" aria-labelledby=\"";
    append_escaped(out, id);
    out += "-title\" font-family=\"ui-monospace, 'DejaVu Sans Mono', Menlo, Consolas, monospace\" font-size=\"11\">";
    out += "<title id=\"";
    append_escaped(out, id);
    out += "-title\">";
    append_escaped(out, options.title);
    out += "</title>";
    out += "<defs><pattern id=\"";
    append_escaped(out, id);
    out += "-hatch\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\" patternTransform=\"rotate(45)\">"
           "<rect width=\"6\" height=\"6\" fill=\"#f4f4f5\"/><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" stroke=\"#a1a1aa\" "
           "stroke-width=\"2\"/></pattern></defs>";

    // Bytes no field covers show this background.
    out += "<rect class=\"unused\" x=\"";
    put(out, label_width);
    out += "\" y=\"";
    put(out, head_height);
    out += "\" width=\"";
    put(out, grid_width);
    out += "\" height=\"";
    put(out, grid_height);
    out += "\" fill=\"#f4f4f5\"/>";

    // Bit numbers over the columns.
    text_element(out, "bit-head", label_width - 6, 14, "end", "byte");
    for (int bit = 0; bit < 8; ++bit)
        text_element(out, "bit-head", label_width + bit * column_width + column_width / 2, 14, "middle", std::to_string(bit));

    // Byte offsets beside the rows; a band shows the range it stands for.
    std::string grid = "M" + std::to_string(label_width) + " " + std::to_string(head_height) + "h" + std::to_string(grid_width);
    {
        std::uint64_t row = 0;
        std::size_t b = 0;
        const auto& bands = rows.bands();
        while (row < byte_count) {
            const long long y = top_of(rows, row);
            if (b < bands.size() && bands[b].first == row) {
                out += "<g class=\"elided\"><title>bytes " + std::to_string(bands[b].first) + "–" + std::to_string(bands[b].last) +
                       "</title>";
                text_element(out, "offset", label_width - 6, y + row_height / 2 + 4, "end", "⋮");
                out += "</g>";
                row = bands[b].last + 1;
                ++b;
            } else {
                text_element(out, "offset", label_width - 6, y + row_height / 2 + 4, "end", std::to_string(row));
                ++row;
            }
            grid += "M" + std::to_string(label_width) + " " + std::to_string(y + row_height) + "h" + std::to_string(grid_width);
        }
    }
    for (int column = 0; column <= 8; ++column)
        grid += "M" + std::to_string(label_width + column * column_width) + " " + std::to_string(head_height) + "v" +
                std::to_string(grid_height);
    out += "<path class=\"grid\" d=\"" + grid + "\" stroke=\"#d4d4d8\" fill=\"none\"/>";

    // The fields, in the order given; each is one group with its accessible label.
    std::size_t p = 0;
    std::vector<const Piece*> own;
    std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
        return a.field != b.field ? a.field < b.field : a.first_row < b.first_row;
    });
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const LayoutField& f = fields[i];
        own.clear();
        while (p < pieces.size() && pieces[p].field == i) own.push_back(&pieces[p++]);
        const MarkStyle mark = mark_style(f.mark);
        const Tint tint = f.mark != FieldMark::none ? mark.tint : group_tints[f.group % group_tints.size()];
        const bool straddles = own.size() > 1;
        const std::string description = field_description(f);

        out += "<g class=\"entry group-" + std::to_string(f.group % group_tints.size());
        if (f.padding) out += " padding";
        if (straddles) out += " straddle";
        if (f.mark != FieldMark::none) {
            out += " mark-";
            out += mark.css;
        }
        out += "\" role=\"img\" aria-label=\"";
        append_escaped(out, description);
        out += "\"><title>";
        append_escaped(out, description);
        out += "</title>";

        const std::string fill = f.padding && f.mark == FieldMark::none ? "url(#" + escaped(id) + "-hatch)" : std::string(tint.fill);
        const std::string_view stroke = f.padding && f.mark == FieldMark::none ? std::string_view("#71717a") : tint.stroke;
        const char* stroke_width = f.mark != FieldMark::none ? "2" : "1";
        if (own.empty()) {  // no bits: a thin marker where it would start
            const long long x = label_width + static_cast<long long>(f.bit_offset % 8) * column_width;
            out += "<rect class=\"piece empty\" x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(top_of(rows, f.bit_offset / 8)) +
                   "\" width=\"3\" height=\"" + std::to_string(row_height) + "\" fill=\"" + std::string(stroke) + "\"/></g>";
            continue;
        }
        const Piece* label_piece = own.front();
        long long label_area = -1;
        for (const Piece* piece : own) {
            const long long x = label_width + piece->first_column * column_width;
            const long long y = top_of(rows, piece->first_row);
            const long long w = (piece->end_column - piece->first_column) * column_width;
            const long long h = top_of(rows, piece->last_row) + row_height - y;
            if (w * h > label_area) {
                label_area = w * h;
                label_piece = piece;
            }
            out += "<rect class=\"piece\" x=\"" + std::to_string(x + 1) + "\" y=\"" + std::to_string(y + 1) + "\" width=\"" +
                   std::to_string(w - 2) + "\" height=\"" + std::to_string(h - 2) + "\" rx=\"3\" fill=\"" + fill + "\" stroke=\"" +
                   std::string(stroke) + "\" stroke-width=\"" + stroke_width + "\"/>";
            if (straddles) {
                // Dashed edges where the field is cut by the end of a byte and goes on in the next row.
                std::string cut;
                if (piece->end_column == 8 && piece->last_row < own.back()->last_row)
                    cut += "M" + std::to_string(x + w - 1) + " " + std::to_string(y + 2) + "v" + std::to_string(h - 4);
                if (piece->first_column == 0 && piece->first_row > own.front()->first_row)
                    cut += "M" + std::to_string(x + 1) + " " + std::to_string(y + 2) + "v" + std::to_string(h - 4);
                if (!cut.empty())
                    out += "<path class=\"cut\" d=\"" + cut + "\" stroke=\"#18181b\" stroke-width=\"2\" stroke-dasharray=\"3 3\" fill=\"none\"/>";
            }
        }
        {
            const long long x = label_width + label_piece->first_column * column_width;
            const long long y = top_of(rows, label_piece->first_row);
            const long long w = (label_piece->end_column - label_piece->first_column) * column_width;
            const long long h = top_of(rows, label_piece->last_row) + row_height - y;
            const auto columns = static_cast<std::size_t>(std::max(0.0, (static_cast<double>(w) - 10) / char_width));
            const std::string shown = f.padding && f.name.empty() ? std::string("padding") : f.name;
            const bool two_lines = h >= 2 * row_height && !f.type.empty();
            const long long text_y = two_lines ? y + h / 2 - 2 : y + std::min<long long>(h, row_height) / 2 + 4;
            text_element(out, "label", x + w / 2, text_y, "middle", shortened(shown, columns));
            if (two_lines)
                text_element(out, "type", x + w / 2, text_y + 14, "middle", shortened(f.type + " · " + plural_bits(f.bit_size), columns));
            if (f.mark != FieldMark::none) text_element(out, "badge", x + 6, y + 12, "start", mark.badge);
        }
        out += "</g>";
    }

    // Elided bands are drawn over the boxes they cut through.
    for (const Band& b : rows.bands()) {
        const long long y = top_of(rows, b.first);
        out += "<path class=\"elision\" d=\"M" + std::to_string(label_width) + " " + std::to_string(y + 8) + "h" +
               std::to_string(grid_width) + "M" + std::to_string(label_width) + " " + std::to_string(y + row_height - 8) + "h" +
               std::to_string(grid_width) + "\" stroke=\"#71717a\" stroke-dasharray=\"2 4\" fill=\"none\"/>";
    }
    out += "</svg>";
    return out;
}

}  // namespace esi::doc
