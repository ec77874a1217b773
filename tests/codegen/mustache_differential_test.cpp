// esi-gen's own Mustache engine against kainjow (the engine esi-gen used before, kept as the test
// oracle in kainjow_oracle.hpp): every shipped template over the views of the sample devices and
// of corpus files renders byte for byte the same, and so do small templates that exercise each
// feature the engine supports over a hand-made view.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "codegen/document_view.hpp"
#include "codegen/view_json.hpp"
#include "esi/codegen/mustache.hpp"
#include "esi/xml/reader.hpp"
#include "esi/yaml/source.hpp"
#include "kainjow_oracle.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
namespace cg = esi::codegen;
namespace mu = esi::codegen::mustache;
using esi::test::codegen::kainjow_render;
using Json = nlohmann::ordered_json;

struct Shipped {
    std::string name;
    std::string text;
};

std::vector<Shipped> shipped_templates() {
    std::vector<Shipped> out;
    for (const auto& e : fs::directory_iterator(esi::test::source_dir() / "templates"))
        if (e.path().extension() == ".mustache") out.push_back({e.path().filename().string(), esi::test::read_text(e.path())});
    std::sort(out.begin(), out.end(), [](const Shipped& a, const Shipped& b) { return a.name < b.name; });
    return out;
}

std::optional<esi::EsiDocument> load(const fs::path& path) {
    if (path.extension() == ".yaml") {
        auto loaded = esi::load_device_source_file(path);
        if (loaded.diagnostics.has_errors()) return std::nullopt;
        return std::move(loaded.document);
    }
    auto read = esi::read_esi_file(path);
    if (read.diagnostics.has_errors()) return std::nullopt;
    return std::move(read.document);
}

// Where two long texts part, with the line of each (whole outputs would drown the message).
std::string first_difference(const std::string& actual, const std::string& expected) {
    const auto [a, e] = std::mismatch(actual.begin(), actual.end(), expected.begin(), expected.end());
    const std::size_t at = static_cast<std::size_t>(a - actual.begin());
    const std::size_t line_start = actual.rfind('\n', at == 0 ? 0 : at - 1);
    const std::size_t from = line_start == std::string::npos ? 0 : line_start + 1;
    const auto line_of = [&](const std::string& s) {
        const std::size_t end = s.find('\n', at);
        return s.substr(from, (end == std::string::npos ? s.size() : end) - from);
    };
    (void)e;
    return "outputs differ at byte " + std::to_string(at) + " (line " + std::to_string(std::count(actual.begin(), a, '\n') + 1) +
           ")\n  esi-gen: " + line_of(actual) + "\n  kainjow: " + line_of(expected);
}

// Renders every shipped template for every device of `path` (at most `max_devices`, spread over
// the file) with both engines; returns how many renderings were compared.
std::size_t expect_same_for_file(const fs::path& path, const std::vector<Shipped>& templates, std::size_t max_devices = 1000) {
    SCOPED_TRACE(path.filename().string());
    const auto document = load(path);
    EXPECT_TRUE(document) << "could not load " << path;
    if (!document) return 0;
    cg::DocumentView view = cg::build_document_view(*document, {});
    EXPECT_FALSE(view.devices.empty());

    std::vector<std::pair<std::string, mu::Template>> parsed;
    for (const auto& t : templates) {
        auto p = mu::parse(t.text);
        EXPECT_TRUE(p.parsed) << t.name << ": " << p.error;
        if (p.parsed) parsed.emplace_back(t.name, std::move(*p.parsed));
    }

    const std::size_t step = std::max<std::size_t>(1, view.devices.size() / max_devices);
    std::size_t compared = 0;
    for (std::size_t d = 0; d < view.devices.size(); d += step) {
        const auto& device = view.devices[d];
        SCOPED_TRACE(device.c_name);
        const cg::ViewValue context = cg::device_context(view, device);
        const Json json = cg::to_json(context);
        for (std::size_t k = 0; k < parsed.size(); ++k) {
            SCOPED_TRACE(parsed[k].first);
            const auto expected = kainjow_render(templates[k].text, json);
            if (!expected.ok) {
                ADD_FAILURE() << "kainjow: " << expected.error;
                return compared;
            }
            std::string actual;
            parsed[k].second.render(context, actual);
            if (actual != expected.text) {
                ADD_FAILURE() << first_difference(actual, expected.text);
                return compared;
            }
            EXPECT_FALSE(actual.empty());
            ++compared;
        }
    }
    return compared;
}

TEST(MustacheDifferential, ShippedTemplatesOverTheSamples) {
    const auto templates = shipped_templates();
    ASSERT_GE(templates.size(), 7u);
    std::vector<fs::path> sources;
    for (const auto& dir : {esi::test::source_dir() / "samples", esi::test::source_dir() / "samples" / "esi"})
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".yaml" || e.path().extension() == ".xml") sources.push_back(e.path());
    sources.push_back(esi::test::source_dir() / "tests" / "codegen" / "data" / "rich-device.xml");
    std::sort(sources.begin(), sources.end());
    ASSERT_GE(sources.size(), 7u);  // five YAML samples, the ESI sample, the rich test device
    std::size_t compared = 0;
    for (const auto& source : sources) compared += expect_same_for_file(source, templates);
    EXPECT_GE(compared, sources.size() * templates.size());
}

TEST(MustacheDifferential, ShippedTemplatesOverCorpusFiles) {
    ESI_REQUIRE_CORPUS();
    const auto templates = shipped_templates();
    std::size_t compared = 0;
    for (const char* name : {"SOES__linux_lan9252demo__soes.xml", "SOES__rtl_xmc4_dynpdo__soes.xml", "ABT__EasyCAT_V2_0__soes.xml",
                             "Synapticon__SOMANET_CiA_402__sc_sncn_ethercat_drive__2017-04.xml",  // CiA 402 servo drive
                             "Copley__XE2_4.60__EtherCAT-ESI-File-Examples__b.xml",               // servo drive, large dictionary
                             "Beckhoff__AX5xxx__dls-ethercat.xml",                                 // servo drive family
                             "MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-10.xml"})
        compared += expect_same_for_file(esi::test::corpus_esi_dir() / name, templates);
    // The large Beckhoff catalogues: a spread of their devices (kainjow is slow on all of them).
    for (const char* name : {"Beckhoff__EL3xxx__dls-ethercat.xml", "Beckhoff__EL66xx__dls-ethercat.xml"})
        compared += expect_same_for_file(esi::test::corpus_esi_dir() / name, templates, 40);
    EXPECT_GT(compared, 100u * templates.size());
}

// A view with every kind of value, for the feature cases below.
Json feature_view() {
    return Json::parse(R"({
        "name": "Chris", "empty": "", "zero": 0, "neg": -12, "big": 18446744073709551615, "real": 2.5,
        "yes": true, "no": false, "nothing": null, "html": "<a href=\"x\">&'</a>",
        "list": [ {"n": "a", "v": 1}, {"n": "b", "v": 2, "name": "inner"}, {"n": "c", "v": 3} ],
        "words": ["x", "y", "z"], "none": [],
        "obj": { "a": { "b": { "c": "deep" } }, "n": "obj-n" },
        "a": { "x": "outer-a-x" },
        "nested": [ [1, 2], [3] ]
    })");
}

struct Case {
    const char* what;
    const char* tmpl;
};

// Each case renders the same with both engines, with and without HTML escaping.
TEST(MustacheDifferential, FeatureCasesMatchKainjow) {
    const Case cases[] = {
        {"plain text", "Hello, world!\n"},
        {"variable", "Hello, {{name}}!"},
        {"missing variable", "[{{missing}}]"},
        {"numbers and booleans", "{{zero}} {{neg}} {{big}} {{real}} [{{yes}}] [{{no}}] [{{nothing}}] [{{list}}] [{{obj}}]"},
        {"escaping", "{{html}} {{{html}}} {{&html}} {{& html }}"},
        {"spaces inside tags", "{{ name }} {{# yes }}y{{/ yes }}{{^ no }}n{{/ no }}"},
        {"dotted names", "{{obj.a.b.c}} {{obj.n}} {{obj.a.missing}} {{obj.missing.c}}"},
        {"dotted name through the context stack", "{{#list}}{{a.x}} {{obj.n}};{{/list}}"},
        {"dotted section", "{{#obj.a.b}}{{c}}{{/obj.a.b}}"},
        {"implicit iterator", "{{#words}}<{{.}}>{{/words}}"},
        {"nested lists", "{{#nested}}[{{#.}}{{.}},{{/.}}]{{/nested}}"},
        {"list of objects", "{{#list}}{{n}}={{v}} {{/list}}"},
        {"context stack lookup", "{{#list}}{{name}},{{/list}}"},
        {"object section", "{{#obj}}{{n}}{{/obj}}"},
        {"value section", "{{#name}}[{{.}}]{{/name}} {{#zero}}z{{/zero}} {{#empty}}e{{/empty}}"},
        {"falsey sections", "{{#no}}1{{/no}}{{#nothing}}2{{/nothing}}{{#none}}3{{/none}}{{#missing}}4{{/missing}}"},
        {"inverted sections", "{{^no}}1{{/no}}{{^nothing}}2{{/nothing}}{{^none}}3{{/none}}{{^missing}}4{{/missing}}{{^yes}}5{{/yes}}{{^list}}6{{/list}}"},
        {"implicit iterator in an inverted section", "{{^no}}[{{.}}]{{/no}}{{^none}}[{{.}}]{{/none}}"},
        {"comment", "a{{! a comment }}b"},
        {"multi-line comment", "a{{! one\ntwo }}b\n"},
        {"standalone section lines", "begin\n{{#list}}\n  {{n}}\n{{/list}}\nend\n"},
        {"indented standalone lines", "begin\n  {{#yes}}\n  yes\n  {{/yes}}\n  {{^yes}}\n  no\n  {{/yes}}\nend\n"},
        {"standalone false section", "a\n{{#no}}\nhidden\n{{/no}}\nb\n"},
        {"standalone comment", "a\n  {{! note }}\nb\n"},
        {"standalone lines with CRLF", "a\r\n{{#yes}}\r\nb\r\n{{/yes}}\r\nc\r\n"},
        {"standalone tag on the last line", "a\n{{#yes}}\nb\n{{/yes}}"},
        {"not standalone: text on the line", "a {{#yes}}\nb\n{{/yes}} c\n"},
        {"not standalone: two tags", "{{#yes}}{{#yes}}\nx\n{{/yes}}{{/yes}}\n"},
        {"variable alone on a line stays", "a\n{{name}}\n{{missing}}\nb\n"},
        {"blank line from a section is dropped", "a\n{{#yes}}  {{/yes}}\nb\n"},
        {"blank line from an empty list", "a\n  {{#none}}x{{/none}}  \nb\n"},
        {"line made blank by a variable", "a\n  {{empty}}  \nb\n"},
        {"inline sections in a list line", "{{#list}}{{n}}{{^v}}!{{/v}}, {{/list}}\n"},
        {"lone CR", "a\rb{{#yes}}\r{{/yes}}c\n"},
        {"tabs", "\t{{#list}}\t\n\t{{n}}\n\t{{/list}}\t\nz"},
        {"no trailing newline", "{{name}}"},
        {"empty template", ""},
        {"braces in text", "{ } {not a tag} }} {"},
        {"space before the sigil", "a\n{{ #yes }}\nb\n{{ /yes }}\n{{ #no }}\nc\n{{ /no }}\n  {{ ! note }}\nd\n"},
        {"standalone comment over lines", "Begin.\n{{!\nSomething's going on here\n}}\nEnd.\n"},
        {"blanks and CRs after a standalone tag", "a\n{{#yes}} \r\nb\n{{/yes}}\r\r\nc"},
        {"set delimiters inline", "{{=<% %>=}}(<%name%>) <%#list%><%n%><%/list%> {{name}} <%={{ }}=%>{{name}}"},
        {"set delimiters with section lines", "a\n{{#no}}\nx\n{{/no}}\n{{=| |=}}\n|#list|\n  |n|\n|/list|\n|^none|\n!\n|/none|\nz\n"},
        {"set delimiters with spaces", "{{= [ ] =}}[#words][.][/words] {{name}}"},
        {"deeply nested sections", "{{#obj}}{{#a}}{{#b}}{{c}}{{n}}{{name}}{{/b}}{{/a}}{{/obj}}"},
    };
    const Json view = feature_view();
    esi::codegen::ViewArena arena;
    const cg::ViewValue context = cg::from_json(arena, view);
    for (const bool html : {false, true}) {
        for (const auto& c : cases) {
            SCOPED_TRACE(std::string(c.what) + (html ? " (HTML)" : ""));
            const auto expected = kainjow_render(c.tmpl, view, html);
            ASSERT_TRUE(expected.ok) << expected.error;
            auto parsed = mu::parse(c.tmpl);
            ASSERT_TRUE(parsed.parsed) << parsed.error;
            std::string actual;
            parsed.parsed->render(context, actual, html ? mu::Escape::html : mu::Escape::none);
            EXPECT_EQ(actual, expected.text) << "template: " << c.tmpl;
        }
    }
}

// Templates strung together at random from tag and text pieces (a fixed seed: the same every
// run): whatever kainjow renders, the engine renders the same, and what kainjow refuses it
// refuses too, except partials and inheritance, which it refuses and kainjow renders as nothing.
TEST(MustacheDifferential, RandomTemplatesMatchKainjow) {
    const char* pieces[] = {"{{", "}}", "{{{", "}}}", "#", "^", "/", "!", "=", ".", "a", "b", "list", "t", "f", "n", "\n",
                            "\r\n", "\r", " ", "\t", "&", "{", "}", ">", "x", "{{#list}}", "{{/list}}", "{{#t}}", "{{/t}}",
                            "{{^f}}", "{{/f}}", "{{a.b}}", "{{.}}", "{{=<% %>=}}", "<%", "%>", "{{!", "{{ #t }}", "{{ /t }}"};
    const Json view = Json::parse(R"({"a": {"b": "AB", "n": 1}, "b": "B", "list": [{"n": "1"}, {"n": 2, "a": {"b": "inner"}}, "s"],
                                     "t": true, "f": false, "n": null, "x": []})");
    cg::ViewArena arena;
    const cg::ViewValue context = cg::from_json(arena, view);
    std::mt19937 rng(20261122);
    std::size_t rendered = 0, refused = 0;
    for (int i = 0; i < 5000; ++i) {
        std::string tmpl;
        const auto length = 1 + rng() % 14;
        for (unsigned k = 0; k < length; ++k) tmpl += pieces[rng() % std::size(pieces)];
        const bool html = i % 2 == 1;
        const auto expected = kainjow_render(tmpl, view, html);
        const auto parsed = mu::parse(tmpl);
        if (!parsed.parsed) {
            if (parsed.error.find("not supported") == std::string::npos) {
                EXPECT_FALSE(expected.ok) << Json(tmpl).dump() << " refused (" << parsed.error << "), kainjow renders " << Json(expected.text).dump();
            }
            ++refused;
            continue;
        }
        ASSERT_TRUE(expected.ok) << Json(tmpl).dump() << " rendered, kainjow refuses: " << expected.error;
        std::string actual;
        parsed.parsed->render(context, actual, html ? mu::Escape::html : mu::Escape::none);
        ASSERT_EQ(actual, expected.text) << Json(tmpl).dump();
        ++rendered;
    }
    EXPECT_GT(rendered, 1000u);
    EXPECT_GT(refused, 1000u);
}

}  // namespace
