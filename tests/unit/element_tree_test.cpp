// The reader's own parser (xml/tree_parser.hpp) builds the tree pugixml built with the reader's
// former options (parse_default | parse_embed_pcdata): the same elements, names, attribute values,
// text (own text and pcdata/cdata children) in the same order, for every corpus file, its CRLF
// and one-line variants and the edge cases below. Each element's line:column is where
// SourceText's position cursor puts pugixml's offset of it, and the line index the parser
// collects is SourceText's.
// pugixml is the reference here: a reader we did not write.

#include <gtest/gtest.h>

#include <pugixml.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "esi/encoding.hpp"
#include "esi/source_text.hpp"
#include "support/test_support.hpp"
#include "xml/tree_parser.hpp"

namespace {

using esi::xml_tree::Element;
using esi::xml_tree::NodeKind;

std::string where(const pugi::xml_node n) { return std::string("<") + n.name() + "> at offset " + std::to_string(n.offset_debug()); }

// The first difference between our element `ours` and pugixml's `theirs` (recursively), or "".
// Plain compares rather than a gtest assertion per field: the corpus has 2.5 million elements to
// compare in its three variants.
std::string difference(const Element ours, const pugi::xml_node theirs, esi::PositionCursor& source, int& elements) {
    ++elements;
    if (ours.kind() != NodeKind::element || ours.name() != theirs.name()) return where(theirs) + ": ours is <" + std::string(ours.name()) + ">";
    const std::string_view own_text = ours.node().has_value ? ours.value() : std::string_view();
    if (own_text != theirs.value()) return where(theirs) + ": own text '" + std::string(own_text) + "', pugixml's '" + theirs.value() + "'";
    // pugixml's offset of an element is that of its name, right after the '<'.
    const auto offset = static_cast<std::size_t>(theirs.offset_debug()) - 1;
    if (ours.offset() != offset) return where(theirs) + ": ours at offset " + std::to_string(ours.offset());
    const esi::SourcePos pos = source.position_of(offset);
    if (ours.pos() != pos)
        return where(theirs) + ": ours at " + std::to_string(ours.pos().line) + ":" + std::to_string(ours.pos().column) + ", SourceText says " +
               std::to_string(pos.line) + ":" + std::to_string(pos.column);
    auto attribute = ours.attributes().begin();
    for (const pugi::xml_attribute a : theirs.attributes()) {
        if (attribute == ours.attributes().end()) return where(theirs) + ": pugixml has more attributes";
        if (attribute->name != a.name() || attribute->value != a.value())
            return where(theirs) + ": attribute " + std::string(attribute->name) + "='" + std::string(attribute->value) + "', pugixml's " +
                   a.name() + "='" + a.value() + "'";
        ++attribute;
    }
    if (attribute != ours.attributes().end()) return where(theirs) + ": ours has more attributes";
    Element c = ours.first_child();
    for (const pugi::xml_node t : theirs.children()) {
        if (!c) return where(theirs) + ": pugixml has more children";
        switch (t.type()) {
            case pugi::node_element:
                if (std::string d = difference(c, t, source, elements); !d.empty()) return d;
                break;
            case pugi::node_pcdata:
            case pugi::node_cdata:
                if (c.kind() != (t.type() == pugi::node_pcdata ? NodeKind::pcdata : NodeKind::cdata) || c.value() != t.value())
                    return where(theirs) + ": text child '" + std::string(c.value()) + "', pugixml's '" + t.value() + "'";
                break;
            default:
                return where(theirs) + ": pugixml has a child of type " + std::to_string(t.type());
        }
        c = c.next_sibling();
    }
    if (c) return where(theirs) + ": ours has more children";
    return {};
}

// Parses `text` (UTF-8) both ways and compares; returns the number of elements compared.
int compare_with_pugixml(const std::string& text, const std::string& what) {
    SCOPED_TRACE(what);
    pugi::xml_document theirs;
    const auto parsed = theirs.load_buffer(text.data(), text.size(), pugi::parse_default | pugi::parse_embed_pcdata, pugi::encoding_utf8);
    EXPECT_TRUE(parsed) << parsed.description();

    esi::xml_tree::Tree tree;
    esi::xml_tree::TreeParser parser(text, esi::SourceEncoding::utf8, tree);
    const Element root = parser.root();
    EXPECT_TRUE(root);
    if (!root) return 0;
    EXPECT_TRUE(parser.expand(root));
    EXPECT_TRUE(parser.finish());
    EXPECT_FALSE(parser.fault()) << parser.fault()->message;

    const esi::SourceText source("test.xml", text);  // its own line index, not the parser's
    esi::PositionCursor cursor(source);                // offsets in document order, a long line counted once
    int elements = 0;
    EXPECT_EQ(difference(root, theirs.document_element(), cursor, elements), "");

    const esi::LineStartList lines = parser.take_line_starts();
    EXPECT_EQ(lines.size(), source.line_count());
    for (std::size_t i = 0; i < std::min(lines.size(), source.line_count()); ++i) {
        if (lines[i] == source.line_start(static_cast<std::uint32_t>(i + 1))) continue;
        ADD_FAILURE() << "line " << i + 1 << " starts at " << lines[i] << ", SourceText says " << source.line_start(static_cast<std::uint32_t>(i + 1));
        break;
    }
    return elements;
}

std::string with_crlf(const std::string& text) {
    std::string out;
    out.reserve(text.size() + text.size() / 16);
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n' && (i == 0 || text[i - 1] != '\r')) out += '\r';
        out += text[i];
    }
    return out;
}

// Line breaks between tags removed (a file written on one line), indentation kept.
std::string on_one_line(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if ((c == '\n' || c == '\r') && i > 0 && (out.empty() || out.back() == '>')) continue;
        out += c;
    }
    return out;
}

TEST(ElementTree, EdgeCasesReadAsPugixmlReadsThem) {
    const std::vector<std::pair<const char*, std::string>> cases = {
        {"own text and children", "<a>x<b/>y<c>z</c> w </a>"},
        {"white space only is dropped", "<a>  <b> \r\n\t</b>\n</a>"},
        {"leading white space of text is kept", "<a><b>  x </b><c>\n y\n</c></a>"},
        {"text after a comment", "<a><!-- c -->text<!-- d -->more</a>"},
        {"text before and after a processing instruction", "<a>x<?pi data?>y</a>"},
        {"CDATA sections", "<a><![CDATA[<x> & ]]><b/><![CDATA[]]>t<![CDATA[\r\nz\r]]></a>"},
        {"CDATA first, then text", "<a><![CDATA[c]]>text</a>"},
        {"references", "<a x='&lt;&gt;&amp;&apos;&quot;' y=\"&#65;&#x42;&#x10FFFF;\">&#9;&amp;lt;&#xE9;&#1234;</a>"},
        {"carriage returns in text", "<a>x\r\ny\rz\r\n</a>"},
        {"attribute normalization", "<a x=\"1\t2\n3\r\n4\r5 6\" y='\r\n' z=\"&#10;&#13;&#9;\"/>"},
        {"entities of a DOCTYPE stay as written", "<!DOCTYPE a [<!ENTITY e \"v\">]><a x=\"&e;\">&e;&amp;&e;</a>"},
        {"names beyond ASCII", "<a\xC3\xA4 b\xC3\xB6=\"\xE2\x82\xAC\">\xC3\xBC<x\xC2\xB7y/></a\xC3\xA4>"},
        {"text beyond ASCII before a tag on the same line", "<a>\xE4\xB8\xAD\xE6\x96\x87<b>\xC3\xA9</b><c/>\xF0\x9F\x98\x80<d/></a>"},
        {"spaces in tags", "<a  x = \"1\"\n y\t=\t'2' ><b\n/><c ></c\n ></a >"},
        {"empty elements", "<a/>"},
        {"deep nesting", [] {
             std::string s;
             for (int i = 0; i < 300; ++i) s += "<e" + std::to_string(i % 7) + ">";
             s += "x";
             for (int i = 299; i >= 0; --i) s += "</e" + std::to_string(i % 7) + ">";
             return s;
         }()},
        {"sixteen and more attributes", [] {
             std::string s = "<a";
             for (int i = 0; i < 40; ++i) s += " a" + std::to_string(i) + "='" + std::to_string(i) + "'";
             return s + "/>";
         }()},
        {"long text and values", "<a x=\"" + std::string(100, 'v') + "\">" + std::string(1000, 't') + "<b>" + std::string(70, ' ') +
                                      "w" + std::string(70, ' ') + "</b></a>"},
        {"a long line", [] {
             std::string s = "<a>";
             for (int i = 0; i < 2000; ++i) s += "<b n=\"\xC3\xA9\">\xC3\xA9" + std::to_string(i) + "</b>";
             return s + "</a>";
         }()},
        {"prolog and trailer", "<?xml version=\"1.0\"?>\n<!-- x -->\n<?pi?>\n<a>\n</a>\n<!-- y -->\n<?z?>\n\n"},
        {"']' and '>' in text", "<a>]] ] > ]]&gt; a]b</a>"},
        // Attributes of inner tags, most of which the inner loop reads itself.
        {"attributes of inner tags", "<r>\n <a x=\"1\" y-z.9='two'>v</a>\n <b k=\"\"/><c  k=\"x\"  /><d k=\"1\" >t</d>"
                                     "<e k=\"a>b\" l='\"q\"' m=\"\xC3\xA9\xE2\x82\xAC\"/><f k=\"&amp;\" l=\"a\tb\"><g/></f>"
                                     "<h xml:lang=\"de\" k=\"1\"/><i k=\"1\" xmlns=\"urn:x\"/><j _k=\"1\"/></r>"},
        {"up to and beyond eight attributes of an inner tag", [] {
             std::string s = "<r>";
             for (int n = 7; n <= 10; ++n) {
                 s += "<a";
                 for (int i = 0; i < n; ++i) s += " a" + std::to_string(i) + "=\"" + std::to_string(i) + "\"";
                 s += ">x</a>";
             }
             return s + "</r>";
         }()},
    };
    for (const auto& [name, xml] : cases) compare_with_pugixml(xml, name);
}

// An inner start tag's attributes fault as the root's do, whether or not the inner loop reads
// them itself.
TEST(ElementTree, FaultsInTheAttributesOfInnerTags) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"<r>\n<a x=\"1\" x=\"2\"/></r>", "attribute 'x' is given twice in the start tag of 'a'"},
        {"<r>\n<a x=\"1\"y=\"2\"/></r>", "whitespace expected before an attribute of 'a'"},
        {"<r>\n<a x=\"1</a></r>", "'<' inside the value of attribute 'x' (write &lt;)"},
        {"<r>\n<a x=1/></r>", "the value of attribute 'x' must be quoted"},
        {"<r>\n<a x=\"&bogus;\"/></r>", ""},
    };
    for (const auto& [text, message] : cases) {
        SCOPED_TRACE(text);
        esi::xml_tree::Tree tree;
        esi::xml_tree::TreeParser parser(text, esi::SourceEncoding::utf8, tree);
        const Element root = parser.root();
        ASSERT_TRUE(root);
        EXPECT_FALSE(parser.expand(root));
        ASSERT_TRUE(parser.fault());
        if (!message.empty()) {
            EXPECT_EQ(parser.fault()->message, message);
        }
        EXPECT_EQ(parser.position_of(text.data() + parser.fault()->offset).line, 2u);
    }
}

TEST(ElementTree, CorpusFilesReadAsPugixmlReadsThem) {
    ESI_REQUIRE_CORPUS();
    std::size_t files = 0;
    int elements = 0;
    for (const auto& entry : std::filesystem::directory_iterator(esi::test::corpus_esi_dir())) {
        if (entry.path().extension() != ".xml") continue;
        const esi::DecodedText decoded = esi::decode_xml_bytes(esi::test::read_text(entry.path()));
        {
            // Only the well-formed ones: the malformed one of the manifest is refused by both.
            pugi::xml_document probe;
            if (!probe.load_buffer(decoded.utf8.data(), decoded.utf8.size(), pugi::parse_default, pugi::encoding_utf8)) continue;
        }
        if (esi::find_well_formedness_fault(decoded.utf8, decoded.encoding)) continue;
        const std::string name = entry.path().filename().string();
        elements += compare_with_pugixml(decoded.utf8, name);
        compare_with_pugixml(with_crlf(decoded.utf8), name + " (CRLF)");
        compare_with_pugixml(on_one_line(decoded.utf8), name + " (one line)");
        ++files;
        if (HasFailure()) break;  // one file's account is enough to read
    }
    EXPECT_GT(files, 80u);
    EXPECT_GT(elements, 500000);
}

}  // namespace
