#include "xml/writer_emitter.hpp"

#include <cassert>

#include "esi/xml_text.hpp"

namespace esi::xml_writer {

// ---- numbers ------------------------------------------------------------------------------

NumberText NumberText::decimal(std::uint64_t value) {
    NumberText t;
    const auto r = std::to_chars(t.buffer_, t.buffer_ + sizeof t.buffer_, value);
    t.length_ = static_cast<std::size_t>(r.ptr - t.buffer_);
    return t;
}

NumberText NumberText::decimal(std::int64_t value) {
    NumberText t;
    const auto r = std::to_chars(t.buffer_, t.buffer_ + sizeof t.buffer_, value);
    t.length_ = static_cast<std::size_t>(r.ptr - t.buffer_);
    return t;
}

NumberText NumberText::decimal(const Number& value) {
    NumberText t;
    char* p = t.buffer_;
    // -0 does not exist in the model's sense (Number::operator== treats it as 0): write "0".
    if (value.negative && value.magnitude != 0) *p++ = '-';
    const auto r = std::to_chars(p, t.buffer_ + sizeof t.buffer_, value.magnitude);
    t.length_ = static_cast<std::size_t>(r.ptr - t.buffer_);
    return t;
}

NumberText NumberText::hex(std::uint64_t value, int min_digits) {
    static constexpr char digits[] = "0123456789ABCDEF";
    char reversed[16];
    int n = 0;
    do {
        reversed[n++] = digits[value & 0xF];
        value >>= 4;
    } while (value != 0);
    NumberText t;
    t.buffer_[t.length_++] = '#';
    t.buffer_[t.length_++] = 'x';
    for (int i = n; i < min_digits && i < 16; ++i) t.buffer_[t.length_++] = '0';
    while (n > 0) t.buffer_[t.length_++] = reversed[--n];
    return t;
}

// ---- names -------------------------------------------------------------------------------

bool is_xml_name(std::string_view name) {
    if (name.empty()) return false;
    const auto start_char = [](unsigned char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == ':' || c >= 0x80;
    };
    if (!start_char(static_cast<unsigned char>(name[0]))) return false;
    for (const char ch : name.substr(1)) {
        const auto c = static_cast<unsigned char>(ch);
        if (!start_char(c) && !(c >= '0' && c <= '9') && c != '-' && c != '.') return false;
    }
    return true;
}

// ---- elements -----------------------------------------------------------------------------

XmlEmitter::XmlEmitter(std::string& out, std::string_view indent, std::string_view line_ending)
    : out_(out), indent_(indent), line_ending_(line_ending) {
    stack_.reserve(32);
    attribute_names_.reserve(16);
}

void XmlEmitter::declaration() {
    out_ += R"(<?xml version="1.0" encoding="UTF-8"?>)";
    at_line_start_ = false;
}

void XmlEmitter::newline_and_indent(std::size_t level) {
    if (!at_line_start_) out_ += line_ending_;
    for (std::size_t i = 0; i < level; ++i) out_ += indent_;
    at_line_start_ = false;
}

void XmlEmitter::close_start_tag() {
    if (!stack_.empty() && stack_.back().tag_open) {
        out_ += '>';
        stack_.back().tag_open = false;
    }
}

void XmlEmitter::begin(std::string_view name) {
    if (!stack_.empty()) {
        close_start_tag();
        stack_.back().has_children = true;
    }
    if (stack_.size() < inline_from_) newline_and_indent(stack_.size());
    out_ += '<';
    out_ += name;
    stack_.push_back(Open{name});
    attribute_names_.clear();
}

void XmlEmitter::attribute(std::string_view name, std::string_view value) {
    assert(!stack_.empty() && stack_.back().tag_open);
    if (stack_.empty() || !stack_.back().tag_open) return;
    for (const std::string_view written : attribute_names_)
        if (written == name) return;  // a repeated attribute would make the file not well-formed
    attribute_names_.push_back(name);
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    append_xml_escaped(out_, value, XmlTextKind::attribute_value);
    out_ += '"';
}

void XmlEmitter::text(std::string_view value) {
    assert(!stack_.empty());
    if (stack_.empty() || value.empty()) return;
    close_start_tag();
    // From here on, whitespace added for indentation would become part of this element's text.
    if (inline_from_ == SIZE_MAX) inline_from_ = stack_.size();
    append_xml_escaped(out_, value, XmlTextKind::character_data);
}

void XmlEmitter::end() {
    assert(!stack_.empty());
    if (stack_.empty()) return;
    const Open top = stack_.back();
    stack_.pop_back();
    if (top.tag_open) {
        out_ += "/>";
    } else {
        if (top.has_children && stack_.size() + 1 < inline_from_) newline_and_indent(stack_.size());
        out_ += "</";
        out_ += top.name;
        out_ += '>';
    }
    if (inline_from_ != SIZE_MAX && stack_.size() < inline_from_) inline_from_ = SIZE_MAX;
}

void XmlEmitter::finish() {
    while (!stack_.empty()) end();
    out_ += line_ending_;
    at_line_start_ = true;
}

}  // namespace esi::xml_writer
