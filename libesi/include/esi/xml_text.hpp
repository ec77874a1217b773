#pragma once
// Text into XML 1.0: the one escaper of every XML libesi writes (the ESI writer, and the XML
// fragments the YAML import carries in `xml` keys). Whatever the string holds, the result is
// well-formed XML 1.0 in UTF-8:
// - & < > are escaped (> too, so that "]]>" never appears), and " inside attribute values;
// - CR is written &#13;, and inside attribute values TAB and LF as &#9; and &#10;: a parser turns
//   a literal CR into LF, and TAB, LF, CR in attribute values into spaces (XML 1.0 §2.11, §3.3.3);
// - the other C0 controls (U+0000-U+001F but TAB, LF, CR) and U+FFFE, U+FFFF are not XML 1.0
//   characters, not even as character references (§2.2): each becomes U+FFFD;
// - invalid UTF-8 (a stray continuation byte, a truncated or overlong sequence, a surrogate, a
//   code point above U+10FFFF) becomes one U+FFFD per byte that starts no valid sequence;
// - everything else, all valid UTF-8 including U+007F-U+009F, is copied unchanged.

#include <string>
#include <string_view>

namespace esi {

enum class XmlTextKind {
    character_data,   // element content
    attribute_value,  // between double quotes
};

void append_xml_escaped(std::string& out, std::string_view text, XmlTextKind kind);

// Text for the parts of XML that take no escapes (a CDATA section, a comment): only what XML
// 1.0 cannot carry is replaced, by U+FFFD as above (C0 controls but TAB, LF, CR; U+FFFE,
// U+FFFF; invalid UTF-8). Markup stays as it is: the caller keeps "]]>" or "--" out.
[[nodiscard]] std::string xml_chars_only(std::string_view text);
[[nodiscard]] std::string xml_escaped(std::string_view text, XmlTextKind kind);

}  // namespace esi
