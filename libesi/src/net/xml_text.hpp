#pragma once
// A small indenting XML text builder for the network writers (ENI, linuxcnc-ethercat): elements
// in the order they are opened, two spaces per level, text and attribute values escaped by the
// project's one escaper (esi/xml_text.hpp), CDATA where a format asks for it. Output is a pure function of the calls, hence deterministic.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "esi/xml_text.hpp"

namespace esi::net {

class XmlText {
public:
    using Attributes = std::vector<std::pair<std::string_view, std::string>>;

    XmlText() { out_ = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"; }

    void open(std::string_view name, const Attributes& attributes = {}) {
        start_tag(name, attributes);
        out_ += ">\n";
        stack_.emplace_back(name);
    }
    void close() {
        indent(stack_.size() - 1);
        out_ += "</" + stack_.back() + ">\n";
        stack_.pop_back();
    }
    void leaf(std::string_view name, std::string_view text, const Attributes& attributes = {}) {
        start_tag(name, attributes);
        out_ += '>';
        escape(text, false);
        out_ += "</";
        out_ += name;
        out_ += ">\n";
    }
    void leaf(std::string_view name, long long value) { leaf(name, std::to_string(value)); }
    void empty(std::string_view name, const Attributes& attributes = {}) {
        start_tag(name, attributes);
        out_ += "/>\n";
    }
    // <name><![CDATA[text]]></name>; a "]]>" in the text is split across two sections, and
    // characters XML cannot carry become U+FFFD (CDATA takes no escapes).
    void cdata_leaf(std::string_view name, std::string_view raw) {
        const std::string chars = xml_chars_only(raw);
        std::string_view text = chars;
        start_tag(name, {});
        out_ += "><![CDATA[";
        for (std::size_t at; (at = text.find("]]>")) != std::string_view::npos; text.remove_prefix(at + 2)) {
            out_.append(text.substr(0, at + 2));
            out_ += "]]><![CDATA[";
        }
        out_.append(text);
        out_ += "]]></";
        out_ += name;
        out_ += ">\n";
    }
    // <!--text-->; "--" may not appear in a comment, so it is written "- -"; characters XML
    // cannot carry become U+FFFD.
    void comment(std::string_view text) {
        std::string t = xml_chars_only(text);
        for (std::size_t at; (at = t.find("--")) != std::string::npos;) t.replace(at, 2, "- -");
        if (!t.empty() && t.back() == '-') t += ' ';
        indent(stack_.size());
        out_ += "<!--" + t + "-->\n";
    }
    std::string finish() {
        while (!stack_.empty()) close();
        return std::move(out_);
    }

    // Text without the declaration (lcec's files carry none).
    void drop_declaration() { out_.clear(); }

private:
    void indent(std::size_t level) { out_.append(level * 2, ' '); }
    void start_tag(std::string_view name, const Attributes& attributes) {
        indent(stack_.size());
        out_ += '<';
        out_ += name;
        for (const auto& [key, value] : attributes) {
            out_ += ' ';
            out_ += key;
            out_ += "=\"";
            escape(value, true);
            out_ += '"';
        }
    }
    // The project's one XML escaper: markup, and characters XML 1.0 cannot carry (controls,
    // invalid UTF-8 in a device name) become U+FFFD, so ENI and lcec files stay well-formed.
    void escape(std::string_view text, bool attribute) {
        append_xml_escaped(out_, text, attribute ? XmlTextKind::attribute_value : XmlTextKind::character_data);
    }

    std::string out_;
    std::vector<std::string> stack_;
};

}  // namespace esi::net
