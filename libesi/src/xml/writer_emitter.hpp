#pragma once
// The XML text emitter of the ESI writer: appends start tags, attributes, escaped character data
// and end tags to one string buffer, with indentation. It knows XML, not ESI: which elements come
// in which order is the business of the model mapping (writer.cpp, writer_device.cpp …).
//
// Output is always well-formed UTF-8 whatever the strings hold: text goes through the XML text
// escaper (esi/xml_text.hpp: markup escaped; invalid UTF-8 and characters XML 1.0 cannot carry
// become U+FFFD), and a repeated attribute name is written once (the first wins).

#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "esi/number.hpp"

namespace esi::xml_writer {

// A number formatted into a small buffer, so that hot paths do not allocate.
class NumberText {
public:
    [[nodiscard]] std::string_view view() const { return {buffer_, length_}; }

    [[nodiscard]] static NumberText decimal(std::uint64_t value);
    [[nodiscard]] static NumberText decimal(std::int64_t value);
    [[nodiscard]] static NumberText decimal(const Number& value);
    // "#x" and at least `min_digits` upper-case hex digits (ETG.2000 HexDecValue).
    [[nodiscard]] static NumberText hex(std::uint64_t value, int min_digits);

private:
    char buffer_[32] = {};
    std::size_t length_ = 0;
};

// An XML 1.0 Name as far as ASCII goes (letters, digits, '_', ':', '-', '.'; not starting with a
// digit, '-' or '.'); bytes >= 0x80 are accepted as name characters.
[[nodiscard]] bool is_xml_name(std::string_view name);

class XmlEmitter {
public:
    XmlEmitter(std::string& out, std::string_view indent, std::string_view line_ending);

    void declaration();  // <?xml version="1.0" encoding="UTF-8"?>

    // Starts an element; attributes may follow until text() or a child begins.
    void begin(std::string_view name);
    void attribute(std::string_view name, std::string_view value);
    // Character data inside the current element. An element with text keeps its children on the
    // same line (mixed content: added whitespace would change the text).
    void text(std::string_view value);
    void end();
    // Ends the document with a line ending.
    void finish();

    // <name>text</name>, or <name/> when text is empty.
    void leaf(std::string_view name, std::string_view text) {
        begin(name);
        if (!text.empty()) this->text(text);
        end();
    }

private:
    struct Open {
        std::string_view name;
        bool tag_open = true;      // '>' not yet written
        bool has_children = false;
    };

    void close_start_tag();
    void newline_and_indent(std::size_t level);

    std::string& out_;
    std::string indent_;
    std::string line_ending_;
    std::vector<Open> stack_;
    std::vector<std::string_view> attribute_names_;  // of the start tag being written
    std::size_t inline_from_ = SIZE_MAX;             // stack depth at which inline output began
    bool at_line_start_ = true;
};

}  // namespace esi::xml_writer
