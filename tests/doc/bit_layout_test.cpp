// The bit-layout picture (esi/doc/bit_layout.hpp): read back as XML, every field is one labelled
// group of boxes at the right place; padding is hatched, straddling fields are cut, long names
// are shortened in the box and whole in the title, long runs of rows are elided.

#include <gtest/gtest.h>

#include <pugixml.hpp>

#include <chrono>
#include <string>
#include <vector>

#include "doc/markup.hpp"
#include "esi/doc/bit_layout.hpp"

namespace {

using esi::doc::FieldMark;
using esi::doc::LayoutField;

LayoutField field(std::string name, std::uint64_t offset, std::uint64_t size, std::string type = "UINT", std::string address = "0x6000:01") {
    LayoutField f;
    f.name = std::move(name);
    f.bit_offset = offset;
    f.bit_size = size;
    f.type = std::move(type);
    f.address = std::move(address);
    return f;
}

struct Picture {
    std::string svg;
    pugi::xml_document xml;
    pugi::xml_node root;
    std::vector<pugi::xml_node> entries;
};

std::unique_ptr<Picture> draw(const std::vector<LayoutField>& fields, std::uint64_t byte_size = 0) {
    auto p = std::make_unique<Picture>();
    esi::doc::BitLayoutOptions options;
    options.id = "pic";
    options.title = "Test picture";
    options.byte_size = byte_size;
    p->svg = esi::doc::render_bit_layout_svg(fields, options);
    const pugi::xml_parse_result parsed = p->xml.load_string(p->svg.c_str());
    EXPECT_TRUE(parsed) << parsed.description() << "\n" << p->svg;
    p->root = p->xml.child("svg");
    for (pugi::xml_node g : p->root.children("g"))
        if (std::string(g.attribute("class").value()).rfind("entry", 0) == 0) p->entries.push_back(g);
    return p;
}

std::vector<pugi::xml_node> pieces(pugi::xml_node entry) {
    std::vector<pugi::xml_node> out;
    for (pugi::xml_node r : entry.children("rect")) out.push_back(r);
    return out;
}

int attr(pugi::xml_node n, const char* name) { return n.attribute(name).as_int(); }

bool has_class(pugi::xml_node n, const std::string& css) {
    const std::string all = std::string(" ") + n.attribute("class").value() + " ";
    return all.find(" " + css + " ") != std::string::npos;
}

TEST(BitLayout, EveryFieldIsOneLabelledGroupWithItsWholeDescription) {
    const auto p = draw({field("Status word", 0, 16, "UINT", "0x6041:00"), field("Enable", 16, 1, "BOOL", "0x7000:01")});
    EXPECT_EQ(std::string(p->root.attribute("role").value()), "group");
    EXPECT_EQ(std::string(p->root.child("title").text().get()), "Test picture");
    ASSERT_EQ(p->entries.size(), 2u);
    EXPECT_EQ(std::string(p->entries[0].attribute("aria-label").value()), "Status word: 0x6041:00, UINT, 16 bits at byte 0 bit 0");
    EXPECT_EQ(std::string(p->entries[0].child("title").text().get()), "Status word: 0x6041:00, UINT, 16 bits at byte 0 bit 0");
    EXPECT_EQ(std::string(p->entries[1].attribute("aria-label").value()), "Enable: 0x7000:01, BOOL, 1 bit at byte 2 bit 0");
    EXPECT_EQ(std::string(p->entries[1].attribute("role").value()), "img");
}

TEST(BitLayout, BytesAreRowsAndBitsAreColumnsWithBitZeroLeft) {
    const auto p = draw({field("A", 0, 16), field("B", 19, 2)});
    const auto a = pieces(p->entries[0]);
    const auto b = pieces(p->entries[1]);
    ASSERT_EQ(a.size(), 1u);  // two whole bytes: one box two rows high
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(attr(a[0], "height") + 2, 2 * 26);
    EXPECT_EQ(attr(a[0], "width") + 2, 8 * 80);
    // B: byte 2, bits 3-4.
    EXPECT_EQ(attr(b[0], "x") - 1, 56 + 3 * 80);
    EXPECT_EQ(attr(b[0], "width") + 2, 2 * 80);
    EXPECT_EQ(attr(b[0], "y") - 1, 20 + 2 * 26);
    // Byte offsets label the rows.
    std::vector<std::string> offsets;
    for (pugi::xml_node t : p->root.children("text"))
        if (std::string(t.attribute("class").value()) == "offset") offsets.push_back(t.text().get());
    EXPECT_EQ(offsets, (std::vector<std::string>{"0", "1", "2"}));
}

TEST(BitLayout, AFieldStraddlingAByteBoundaryIsDrawnInPiecesWithCutEdges) {
    const auto p = draw({field("Head", 0, 6), field("Counter", 6, 12), field("Tail", 18, 6)});
    const pugi::xml_node counter = p->entries[1];
    EXPECT_TRUE(has_class(counter, "straddle"));
    EXPECT_FALSE(has_class(p->entries[0], "straddle"));
    const auto parts = pieces(counter);
    ASSERT_EQ(parts.size(), 3u);  // bits 6-7 of byte 0, byte 1 whole, bits 0-1 of byte 2
    EXPECT_EQ(attr(parts[0], "x") - 1, 56 + 6 * 80);
    EXPECT_EQ(attr(parts[1], "width") + 2, 8 * 80);
    EXPECT_EQ(attr(parts[2], "width") + 2, 2 * 80);
    EXPECT_EQ(std::distance(counter.children("path").begin(), counter.children("path").end()), 3);  // cut edges
    EXPECT_NE(std::string(counter.attribute("aria-label").value()).find("straddles bytes 0–2"), std::string::npos);
}

TEST(BitLayout, WholeBytesAtAByteOffsetDoNotStraddle) {
    const auto p = draw({field("Byte", 0, 8), field("Dword", 8, 32)});
    EXPECT_FALSE(has_class(p->entries[1], "straddle"));
    EXPECT_EQ(pieces(p->entries[1]).size(), 1u);
    EXPECT_EQ(std::string(p->entries[1].attribute("aria-label").value()).find("straddles"), std::string::npos);
}

TEST(BitLayout, PaddingIsHatchedAndLabelled) {
    LayoutField gap = field("", 8, 8, "", "");
    gap.padding = true;
    const auto p = draw({field("A", 0, 8), gap});
    EXPECT_TRUE(has_class(p->entries[1], "padding"));
    EXPECT_EQ(std::string(pieces(p->entries[1])[0].attribute("fill").value()), "url(#pic-hatch)");
    EXPECT_TRUE(p->root.child("defs").find_child_by_attribute("pattern", "id", "pic-hatch"));
    EXPECT_EQ(std::string(p->entries[1].child("text").text().get()), "padding");
    EXPECT_EQ(std::string(p->entries[1].attribute("aria-label").value()), "padding: 8 bits at byte 1 bit 0");
}

TEST(BitLayout, LongNamesAreShortenedInTheBoxAndWholeInTheTitle) {
    const std::string name = "Position actual value of the second encoder channel";
    const auto p = draw({field(name, 0, 1, "BOOL")});
    const std::string shown = p->entries[0].child("text").text().get();
    EXPECT_LT(esi::doc::display_columns(shown), name.size());
    EXPECT_EQ(shown.substr(shown.size() - 3), "…");
    EXPECT_EQ(name.rfind(shown.substr(0, shown.size() - 3), 0), 0u);
    EXPECT_NE(std::string(p->entries[0].child("title").text().get()).find(name), std::string::npos);
}

TEST(BitLayout, TextIsEscaped) {
    const auto p = draw({field("A<B & \"C\"", 0, 8)});
    EXPECT_EQ(std::string(p->entries[0].attribute("aria-label").value()).substr(0, 9), "A<B & \"C\"");
    EXPECT_EQ(p->svg.find("A<B"), std::string::npos);
}

TEST(BitLayout, LongRunsOfRowsInsideOneFieldOrUncoveredAreElided) {
    // A 1 KiB octet string between two bytes, then 1 KiB nothing up to byte_size.
    const auto p = draw({field("Head", 0, 8), field("Blob", 8, 8 * 1024, "OCTET_STRING"), field("Tail", 8 * 1025, 8)}, 2050);
    const int height = attr(p->root, "height");
    EXPECT_LT(height, 20 + 12 * 26 + 10);  // a handful of rows, not 2050
    const auto blob = pieces(p->entries[1]);
    ASSERT_EQ(blob.size(), 1u);
    EXPECT_GE(attr(blob[0], "height") + 2, 3 * 26);  // first two rows, the elided band, the last row
    std::vector<std::string> bands;
    for (pugi::xml_node g : p->root.children("g"))
        if (std::string(g.attribute("class").value()) == "elided") bands.push_back(g.child("title").text().get());
    EXPECT_EQ(bands, (std::vector<std::string>{"bytes 3–1023", "bytes 1027–2048"}));
    // Tail is still drawn at its own row, right after the last row of Blob.
    const auto tail = pieces(p->entries[2]);
    EXPECT_EQ(attr(tail[0], "y"), attr(blob[0], "y") + attr(blob[0], "height") + 2);
}

TEST(BitLayout, HugeOffsetsStayCheapToDraw) {
    const auto start = std::chrono::steady_clock::now();
    const auto p = draw({field("Far", std::uint64_t{1} << 40, 8), field("Huge", 0, std::uint64_t{1} << 36, "OCTET_STRING")});
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
    EXPECT_LT(p->svg.size(), 20000u);
    EXPECT_EQ(p->entries.size(), 2u);
}

TEST(BitLayout, AFieldWithoutBitsIsAMarkerWithItsLabel) {
    const auto p = draw({field("Empty", 8, 0)});
    ASSERT_EQ(p->entries.size(), 1u);
    EXPECT_TRUE(has_class(pieces(p->entries[0])[0], "empty"));
    EXPECT_EQ(std::string(p->entries[0].attribute("aria-label").value()), "Empty: 0x6000:01, UINT, 0 bits at byte 1 bit 0");
}

TEST(BitLayout, AnEmptyListIsAValidPictureOfOneRow) {
    const auto p = draw({});
    EXPECT_TRUE(p->entries.empty());
    EXPECT_GT(attr(p->root, "height"), 0);
    EXPECT_GT(attr(p->root, "width"), 0);
}

TEST(BitLayout, MarksAreToldByClassBadgeAndWordsNotColourAlone) {
    LayoutField added = field("New", 0, 8);
    added.mark = FieldMark::added;
    LayoutField resized = field("Wider", 8, 32);
    resized.mark = FieldMark::resized;
    const auto p = draw({added, resized});
    EXPECT_TRUE(has_class(p->entries[0], "mark-added"));
    EXPECT_TRUE(has_class(p->entries[1], "mark-resized"));
    EXPECT_NE(std::string(p->entries[0].attribute("aria-label").value()).find("(added)"), std::string::npos);
    bool badge = false;
    for (pugi::xml_node t : p->entries[0].children("text")) badge = badge || std::string(t.text().get()) == "+";
    EXPECT_TRUE(badge);
}

TEST(BitLayout, OutputIsDeterministic) {
    const std::vector<LayoutField> fields{field("A", 0, 3), field("B", 3, 13), field("C", 16, 64)};
    EXPECT_EQ(draw(fields)->svg, draw(fields)->svg);
}

TEST(Markup, ShorteningKeepsWholeCharactersAndCountsWideOnesTwice) {
    EXPECT_EQ(esi::doc::shortened("Enable", 10), "Enable");
    EXPECT_EQ(esi::doc::shortened("Enable output", 8), "Enable…");
    EXPECT_EQ(esi::doc::shortened("Ausgänge aktiv", 8), "Ausgäng…");
    EXPECT_EQ(esi::doc::display_columns("Ausgänge"), 8u);
    EXPECT_EQ(esi::doc::display_columns("状态字"), 6u);
    EXPECT_EQ(esi::doc::shortened("状态字状态字", 5), "状态…");
    EXPECT_EQ(esi::doc::shortened("abc", 1), "");
}

TEST(Markup, SlugsAreFileSafe) {
    EXPECT_EQ(esi::doc::slug("EL1008", "x"), "EL1008");
    EXPECT_EQ(esi::doc::slug("AX5101-0000-0010 (2 Ch.)", "x"), "AX5101-0000-0010-2-Ch");
    EXPECT_EQ(esi::doc::slug("../../etc/passwd", "x"), "etc-passwd");
    EXPECT_EQ(esi::doc::slug("äöü", "device"), "device");
}

}  // namespace
