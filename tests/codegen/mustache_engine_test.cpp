// esi-gen's Mustache engine on its own: spec behaviour written out by hand (interpolation,
// escaping, sections, inverted sections, dotted names, the implicit iterator, standalone lines,
// comments, set delimiters) and the diagnostics for what it does not support or cannot parse.

#include <gtest/gtest.h>

#include <string>

#include "codegen/view_json.hpp"
#include "esi/codegen/mustache.hpp"
#include "esi/codegen/view_tree.hpp"

namespace {

namespace cg = esi::codegen;
namespace mu = esi::codegen::mustache;
using Json = nlohmann::ordered_json;

std::string render(const std::string& tmpl, const Json& data, mu::Escape escape = mu::Escape::none) {
    auto parsed = mu::parse(tmpl);
    EXPECT_TRUE(parsed.parsed) << parsed.error << " at " << parsed.pos.line << ":" << parsed.pos.column;
    if (!parsed.parsed) return "<parse error>";
    cg::ViewArena arena;
    std::string out;
    parsed.parsed->render(cg::from_json(arena, data), out, escape);
    return out;
}

struct Failure {
    std::string error;
    std::size_t line = 0, column = 0;
};

Failure parse_error(const std::string& tmpl) {
    const auto parsed = mu::parse(tmpl);
    EXPECT_FALSE(parsed.parsed) << "parsed: " << tmpl;
    return {parsed.error, parsed.pos.line, parsed.pos.column};
}

TEST(MustacheEngine, Interpolation) {
    const Json data = {{"subject", "world"}, {"n", 42}, {"neg", -1}, {"r", 1.5}, {"t", true}, {"z", nullptr}};
    EXPECT_EQ(render("Hello, {{subject}}!\n", data), "Hello, world!\n");
    EXPECT_EQ(render("{{n}} {{neg}} {{r}}", data), "42 -1 1.5");
    EXPECT_EQ(render("[{{t}}][{{z}}][{{missing}}]", data), "[][][]");
    EXPECT_EQ(render("{{ subject }}|{{{ subject }}}|{{& subject }}", data), "world|world|world");
    EXPECT_EQ(render("no tags { } }}", data), "no tags { } }}");
}

TEST(MustacheEngine, EscapingIsHtmlOnlyWhenAskedAndNeverInTripleOrAmpersand) {
    const Json data = {{"s", "a & b < c > d \" e ' f"}};
    EXPECT_EQ(render("{{s}}", data), "a & b < c > d \" e ' f");  // code generation: as it is
    EXPECT_EQ(render("{{s}}", data, mu::Escape::html), "a &amp; b &lt; c &gt; d &quot; e &apos; f");
    EXPECT_EQ(render("{{{s}}}|{{&s}}", data, mu::Escape::html), "a & b < c > d \" e ' f|a & b < c > d \" e ' f");
}

TEST(MustacheEngine, SectionsOverListsObjectsAndValues) {
    const Json data = {{"list", {{{"x", 1}}, {{"x", 2}}, {{"x", 3}}}},
                       {"obj", {{"x", "o"}}},
                       {"t", true},
                       {"f", false},
                       {"z", nullptr},
                       {"empty", Json::array()},
                       {"s", "str"},
                       {"x", "outer"}};
    EXPECT_EQ(render("{{#list}}{{x}},{{/list}}", data), "1,2,3,");
    EXPECT_EQ(render("{{#obj}}{{x}}{{/obj}}", data), "o");
    EXPECT_EQ(render("{{#t}}{{x}}{{/t}}", data), "outer");  // a true section keeps the context
    EXPECT_EQ(render("{{#f}}F{{/f}}{{#z}}Z{{/z}}{{#empty}}E{{/empty}}{{#missing}}M{{/missing}}", data), "");
    EXPECT_EQ(render("{{#s}}<{{.}}>{{/s}}", data), "<str>");
    EXPECT_EQ(render("{{#list}}{{#obj}}{{x}}{{/obj}}{{/list}}", data), "ooo");
}

TEST(MustacheEngine, InvertedSections) {
    const Json data = {{"t", true}, {"f", false}, {"empty", Json::array()}, {"list", {1}}};
    EXPECT_EQ(render("{{^f}}F{{/f}}{{^empty}}E{{/empty}}{{^missing}}M{{/missing}}", data), "FEM");
    EXPECT_EQ(render("{{^t}}T{{/t}}{{^list}}L{{/list}}", data), "");
}

TEST(MustacheEngine, NamesAreLookedUpOutwardsThroughTheContextStack) {
    const Json data = {{"name", "root"}, {"items", {{{"name", "first"}}, {{"other", 1}}}}};
    EXPECT_EQ(render("{{#items}}{{name}};{{/items}}", data), "first;root;");
}

TEST(MustacheEngine, DottedNamesAndTheImplicitIterator) {
    const Json data = {{"a", {{"b", {{"c", "deep"}}}}}, {"words", {"x", "y"}}, {"nums", {1, 2}}};
    EXPECT_EQ(render("{{a.b.c}}|{{a.b.missing}}|{{a.missing.c}}", data), "deep||");
    EXPECT_EQ(render("{{#a.b}}{{c}}{{/a.b}}", data), "deep");
    EXPECT_EQ(render("{{#words}}{{.}}{{/words}}-{{#nums}}{{.}}{{/nums}}", data), "xy-12");
}

TEST(MustacheEngine, StandaloneTagLinesAreRemoved) {
    const Json data = {{"t", true}, {"f", false}, {"list", {{{"n", "a"}}, {{"n", "b"}}}}};
    EXPECT_EQ(render("begin\n{{#list}}\n  {{n}}\n{{/list}}\nend\n", data), "begin\n  a\n  b\nend\n");
    EXPECT_EQ(render("|\n  {{#t}}  \n  yes\n  {{/t}}\n|\n", data), "|\n  yes\n|\n");
    EXPECT_EQ(render("|\n{{#f}}\nno\n{{/f}}\n|\n", data), "|\n|\n");                  // false sections too
    EXPECT_EQ(render("|\r\n{{#t}}\r\nyes\r\n{{/t}}\r\n|\r\n", data), "|\r\nyes\r\n|\r\n");  // CRLF
    EXPECT_EQ(render("|\n{{#t}}\nyes\n{{/t}}", data), "|\nyes\n");                     // last line, no break
    EXPECT_EQ(render("| {{#t}}\nyes\n{{/t}} |\n", data), "| \nyes\n |\n");            // not standalone
    EXPECT_EQ(render("|\n{{x}}\n|\n", data), "|\n\n|\n");                             // variables never are
}

// Where esi-gen's rule (kept from its kainjow days, see mustache.hpp) is narrower than the spec's.
TEST(MustacheEngine, StandaloneRuleIsTheOneEsiGenAlwaysHad) {
    const Json data = {{"t", true}, {"f", false}};
    // A space before the sigil: only kainjow's rule (a blank line touched by a rendered section).
    EXPECT_EQ(render("|\n{{ #t }}\nyes\n{{ /t }}\n|\n", data), "|\nyes\n|\n");
    EXPECT_EQ(render("|\n{{ #f }}\nno\n{{ /f }}\n|\n", data), "|\n\n|\n");
    // A comment over several lines leaves its line.
    EXPECT_EQ(render("Begin.\n{{!\nSomething's going on here\n}}\nEnd.\n", data), "Begin.\n\nEnd.\n");
    // Blanks and carriage returns after the tag count as blanks.
    EXPECT_EQ(render("|\n{{#t}} \r\nyes\n{{/t}}\r\r\n|", data), "|\nyes\n|");
    // A template that sets delimiters keeps its standalone lines unless a rendered section blanks them.
    EXPECT_EQ(render("|\n{{#f}}\nno\n{{/f}}\n{{=<% %>=}}\n<%#t%>\nyes\n<%/t%>\n|\n", data), "|\n\n\nyes\n|\n");
}

TEST(MustacheEngine, Comments) {
    const Json data = Json::object();
    EXPECT_EQ(render("12345{{! Comment Block! }}67890", data), "1234567890");
    EXPECT_EQ(render("Begin.\n  {{! Indented }}  \nEnd.\n", data), "Begin.\nEnd.\n");
    EXPECT_EQ(render("  12 {{! 34 }}\n", data), "  12 \n");
}

TEST(MustacheEngine, SetDelimiters) {
    const Json data = {{"text", "Hey!"}, {"t", true}, {"list", {1, 2}}};
    EXPECT_EQ(render("{{=<% %>=}}(<%text%>)", data), "(Hey!)");
    EXPECT_EQ(render("[\n{{=| |=}}\n|#t|\nyes\n|/t|\n|={{ }}=|\n{{text}}\n]\n", data), "[\n\nyes\n\nHey!\n]\n");
    EXPECT_EQ(render("{{= [ ] =}}[#list][.][/list] {{text}}", data), "12 {{text}}");
    EXPECT_EQ(render("{{=<< >>=}}<<{text}>> <<&text>>", data), " Hey!");  // no triple mustache with other delimiters
}

TEST(MustacheEngine, UnsupportedTagsAreErrorsAtTheirPosition) {
    auto f = parse_error("line one\n  {{> header}}\n");
    EXPECT_NE(f.error.find("partials are not supported"), std::string::npos) << f.error;
    EXPECT_EQ(f.line, 2u);
    EXPECT_EQ(f.column, 3u);
    f = parse_error("{{< base}}{{/base}}");
    EXPECT_NE(f.error.find("inheritance is not supported"), std::string::npos) << f.error;
    f = parse_error("a\nb {{$ block}}x{{/block}}");
    EXPECT_NE(f.error.find("inheritance is not supported"), std::string::npos) << f.error;
    EXPECT_EQ(f.line, 2u);
    EXPECT_EQ(f.column, 3u);
}

TEST(MustacheEngine, MalformedTemplatesAreErrorsAtTheirPosition) {
    auto f = parse_error("ok\n{{#device.objects}}\nunclosed\n");
    EXPECT_EQ(f.error, "Unclosed section \"device.objects\"");
    EXPECT_EQ(f.line, 2u);
    EXPECT_EQ(f.column, 1u);
    f = parse_error("a\n\n   {{/nothing}}");
    EXPECT_EQ(f.error, "Unopened section \"nothing\"");
    EXPECT_EQ(f.line, 3u);
    EXPECT_EQ(f.column, 4u);
    f = parse_error("{{#a}}\n{{#b}}\n{{/a}}\n");
    EXPECT_NE(f.error.find("Unclosed section \"b\""), std::string::npos) << f.error;
    EXPECT_NE(f.error.find("3:1"), std::string::npos) << f.error;  // where the wrong end tag is
    EXPECT_EQ(f.line, 2u);
    f = parse_error("x {{name");
    EXPECT_EQ(f.error, "Unclosed tag");
    EXPECT_EQ(f.column, 3u);
    f = parse_error("{{{name}}");
    EXPECT_EQ(f.error, "Unclosed tag");
    f = parse_error("\n{{=<%>=}}");
    EXPECT_EQ(f.error, "Invalid set delimiter tag");
    EXPECT_EQ(f.line, 2u);
}

TEST(MustacheEngine, NestingDepthIsBounded) {
    std::string deep, ok;
    for (std::size_t k = 0; k < mu::max_section_depth + 1; ++k) deep += "{{#a}}";
    for (std::size_t k = 0; k < mu::max_section_depth + 1; ++k) deep += "{{/a}}";
    const auto f = parse_error(deep);
    EXPECT_NE(f.error.find("nested deeper"), std::string::npos) << f.error;
    for (std::size_t k = 0; k < mu::max_section_depth; ++k) ok += "{{#a}}";
    ok += "{{v}}";
    for (std::size_t k = 0; k < mu::max_section_depth; ++k) ok += "{{/a}}";
    EXPECT_EQ(render(ok, {{"a", true}, {"v", "bottom"}}), "bottom");
}

TEST(MustacheEngine, ATemplateRendersTheSameEachTime) {
    auto parsed = mu::parse("{{#list}}{{n}}{{^last}}, {{/last}}{{/list}}\n");
    ASSERT_TRUE(parsed.parsed);
    cg::ViewArena arena;
    const auto view = cg::from_json(arena, Json{{"list", {{{"n", "a"}}, {{"n", "b"}, {"last", true}}}}});
    std::string first, second;
    parsed.parsed->render(view, first);
    parsed.parsed->render(view, second);
    EXPECT_EQ(first, "a, b\n");
    EXPECT_EQ(first, second);
}

}  // namespace
