// esi-doc's pages as the library renders them (esi/doc/datasheet.hpp): which files, what every
// page holds, that pages stand alone, languages, device selection and templates.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <regex>

#include "doc/page_root.hpp"
#include "doc_test_support.hpp"
#include "esi/doc/datasheet.hpp"

namespace {

namespace fs = std::filesystem;
using esi::test::read_text;
using esi::test::TempDir;
using esi::test::write_text;
using namespace esi::test::doc;

esi::doc::DatasheetOptions default_options() {
    esi::doc::DatasheetOptions options;
    options.template_dirs = esi::doc::template_search_path({}, std::nullopt);
    return options;
}

std::map<std::string, std::string> render(const esi::EsiDocument& document, const esi::doc::DatasheetOptions& options = default_options()) {
    const esi::doc::Datasheets pages = esi::doc::render_datasheets(document, "out", options);
    EXPECT_FALSE(pages.diagnostics.has_errors()) << (pages.diagnostics.empty() ? "" : pages.diagnostics.items().front().message);
    std::map<std::string, std::string> out;
    for (const auto& f : pages.files) out[f.path.generic_string()] = f.content;
    return out;
}

// The one device page of a rendering of a single-device document.
const std::string& device_page(const std::map<std::string, std::string>& pages) {
    EXPECT_EQ(pages.size(), 2u);
    return std::find_if(pages.begin(), pages.end(), [](const auto& p) { return p.first != "out/index.html"; })->second;
}

TEST(Datasheet, AnIndexAndOnePagePerDeviceNamedByTypeAndRevision) {
    const auto document = load(samples_dir() / "digital-io-8.yaml");
    const auto pages = esi::doc::render_datasheets(document, "out", default_options());
    ASSERT_FALSE(pages.diagnostics.has_errors());
    std::vector<std::string> names;
    for (const auto& f : pages.files) names.push_back(f.path.generic_string());
    ASSERT_EQ(names.size(), document.infos.front().devices.size() + 1);
    EXPECT_EQ(names.front(), "out/index.html");
    const std::string& index = pages.files.front().content;
    for (std::size_t i = 1; i < names.size(); ++i) {
        EXPECT_TRUE(std::regex_match(names[i], std::regex("out/[A-Za-z0-9._-]+-rev[0-9A-F]{8}\\.html"))) << names[i];
        EXPECT_NE(index.find("href=\"" + names[i].substr(4) + "\""), std::string::npos) << "index links " << names[i];
    }
}

TEST(Datasheet, EveryPdoEntryOfTheSamplesHasExactlyOneTableRow) {
    for (const fs::path& source : sample_sources()) {
        const esi::EsiDocument document = load(source);
        const auto devices = esi::select_devices(document, std::nullopt);
        const auto names = esi::doc::page_file_names(devices);
        const auto pages = render(document);
        for (std::size_t d = 0; d < devices.size(); ++d) {
            const std::string& page = pages.at("out/" + names[d]);
            const auto keys = expected_entry_keys(document, *devices[d]);
            for (const auto& key : keys) EXPECT_EQ(occurrences(page, "data-entry=\"" + key + "\""), 1u) << source << " " << key;
            EXPECT_EQ(occurrences(page, "data-entry=\""), keys.size()) << source;
        }
    }
}

TEST(Datasheet, EachPdoAndEachDefaultImageHasAPicture) {
    const auto document = load(sample_esi());
    const auto pages = render(document);
    const esi::Device& device = document.infos.front().devices.front();
    const std::string& page = pages.at("out/" + esi::doc::page_file_names({&device}).front());
    const std::size_t pdos = device.rx_pdos.size() + device.tx_pdos.size();
    EXPECT_EQ(occurrences(page, "<svg "), pdos + 2);  // + the SM2 and SM3 images
    EXPECT_NE(page.find("id=\"pic-sm2\""), std::string::npos);
    EXPECT_NE(page.find("id=\"pic-dev-rx0\""), std::string::npos);
}

TEST(Datasheet, PagesStandAloneWithoutScriptsOrRequests) {
    for (const fs::path& source : sample_sources()) {
        for (const auto& [name, html] : render(load(source))) {
            EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u) << name;
            EXPECT_EQ(html.find("<script"), std::string::npos) << name;
            EXPECT_EQ(html.find("<link"), std::string::npos) << name;
            EXPECT_EQ(html.find(" src="), std::string::npos) << name;
            EXPECT_EQ(html.find("@import"), std::string::npos) << name;
            // url( only for the picture's own hatch pattern.
            EXPECT_EQ(occurrences(html, "url("), occurrences(html, "url(#")) << name;
            // Links stay in the page or go to a sibling page.
            for (std::size_t at = html.find("href=\""); at != std::string::npos; at = html.find("href=\"", at + 6)) {
                const std::string target = html.substr(at + 6, html.find('"', at + 6) - at - 6);
                EXPECT_TRUE(target.front() == '#' || std::regex_match(target, std::regex("[A-Za-z0-9._-]+\\.html"))) << name << ": " << target;
            }
            EXPECT_NE(html.find("<style>"), std::string::npos) << name;
        }
    }
}

TEST(Datasheet, RenderingIsDeterministicAndIndependentOfWhereTheFileIs) {
    TempDir a, b;
    const std::string text = read_text(sample_esi());
    write_text(a / "device.xml", text);
    write_text(b.path() / "deeper" / "device.xml", text);
    const auto first = render(load(a / "device.xml"));
    EXPECT_EQ(first, render(load(a / "device.xml")));
    EXPECT_EQ(first, render(load(b.path() / "deeper" / "device.xml")));
}

TEST(Datasheet, NamesComeInTheChosenLanguageAndFallBackToEnglish) {
    const auto document = load(sample_esi());
    auto options = default_options();
    options.lcid = 1031;
    const auto german = render(document, options);
    const std::string& page = device_page(german);
    EXPECT_NE(page.find("<html lang=\"de\">"), std::string::npos);
    EXPECT_NE(page.find("<h1>EX-DIO-8 8 Eingänge, 8 Ausgänge (EX-DIO-8)</h1>"), std::string::npos);
    EXPECT_NE(page.find("Digitale E/A"), std::string::npos);  // the group
    // French is not in the file: English.
    options.lcid = 1036;
    const auto french = render(document, options);
    const std::string& fallback = device_page(french);
    EXPECT_NE(fallback.find("<h1>EX-DIO-8 8 inputs, 8 outputs (EX-DIO-8)</h1>"), std::string::npos);
    // <html lang> names the language the page is read in (WCAG 2.1, 3.1.1): English here.
    EXPECT_NE(fallback.find("<html lang=\"en\">"), std::string::npos);
    EXPECT_NE(french.at("out/index.html").find("<html lang=\"en\">"), std::string::npos);
}

TEST(Datasheet, PageLanguageIsTheLanguageTheNamesAreIn) {
    // A file whose names are German only: German whatever is asked for, as the names fall back to it.
    std::string text = read_text(sample_esi());
    const auto replace = [&](std::string_view from, std::string_view to) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace(R"(<Name LcId="1033">Example Automation GmbH</Name>)", R"(<Name LcId="1031">Beispiel Automation GmbH</Name>)");
    replace(R"(<Name LcId="1033">Digital I/O</Name>)", "");
    replace(R"(<Name LcId="1033">EX-DIO-8 8 inputs, 8 outputs</Name>)", "");
    esi::test::TempDir dir;
    write_text(dir / "german.xml", text);
    const auto document = load(dir / "german.xml");
    auto options = default_options();
    options.lcid = 1036;
    const auto pages = render(document, options);
    EXPECT_NE(device_page(pages).find("<html lang=\"de\">"), std::string::npos);
    EXPECT_NE(device_page(pages).find("Eingänge"), std::string::npos);

    EXPECT_EQ(esi::doc::page_language(1031, {1031, 1033}), 1031u);
    EXPECT_EQ(esi::doc::page_language(1036, {1031, 1033}), 1033u);
    EXPECT_EQ(esi::doc::page_language(1036, {}), 1033u);
    EXPECT_EQ(esi::doc::page_language(1036, {1041, 1031}), 1031u);
}

TEST(Datasheet, LanguagesAreCodesOrLcIds) {
    EXPECT_EQ(esi::doc::parse_language("en"), 1033u);
    EXPECT_EQ(esi::doc::parse_language("de"), 1031u);
    EXPECT_EQ(esi::doc::parse_language("1036"), 1036u);
    EXPECT_EQ(esi::doc::parse_language("klingon"), std::nullopt);
    EXPECT_EQ(esi::doc::parse_language("0"), std::nullopt);
    EXPECT_EQ(esi::doc::parse_language(""), std::nullopt);
}

TEST(Datasheet, DeviceSelectionRendersOnlyThatDeviceAndNoMatchIsAnError) {
    const auto document = load(samples_dir() / "digital-io-8.yaml");
    auto options = default_options();
    options.device = esi::DeviceSelector{0x1002, std::nullopt};
    const auto pages = render(document, options);
    ASSERT_EQ(pages.size(), 2u);
    EXPECT_NE(pages.begin()->first.find("EX-DIO-8B"), std::string::npos);
    options.device = esi::DeviceSelector{0x7777, std::nullopt};
    const auto none = esi::doc::render_datasheets(document, "out", options);
    EXPECT_TRUE(none.files.empty());
    ASSERT_EQ(none.diagnostics.size(), 1u);
    EXPECT_EQ(none.diagnostics.items().front().rule, "doc-no-device");
}

TEST(Datasheet, ATemplateDirectoryReplacesOnlyWhatItHolds) {
    TempDir dir;
    write_text(dir / "device.html.mustache", "<p>{{#device}}{{type}}{{/device}} {{source_file}}</p>\n");
    write_text(dir / "page.css", "body { color: #123456; }\n");
    auto options = default_options();
    options.template_dirs = esi::doc::template_search_path({dir.path()}, std::nullopt);
    const auto pages = render(load(sample_esi()), options);
    EXPECT_EQ(pages.at("out/EX-DIO-8-rev00010000.html"), "<p>EX-DIO-8 example-digital-io.xml</p>\n");
    EXPECT_NE(pages.at("out/index.html").find("body { color: #123456; }"), std::string::npos);  // the built-in index, the new style
}

TEST(Datasheet, ABrokenTemplateIsReportedAtItsLineAndNothingIsRendered) {
    TempDir dir;
    write_text(dir / "index.html.mustache", "<ul>\n{{#devices}}\n<li>{{title}}</li>\n");
    auto options = default_options();
    options.template_dirs = esi::doc::template_search_path({dir.path()}, std::nullopt);
    const auto pages = esi::doc::render_datasheets(load(sample_esi()), "out", options);
    EXPECT_TRUE(pages.files.empty());
    ASSERT_TRUE(pages.diagnostics.has_errors());
    const esi::Diagnostic& d = pages.diagnostics.items().front();
    EXPECT_EQ(d.rule, "doc-template-error");
    EXPECT_EQ(fs::path(d.path).filename(), "index.html.mustache");
    EXPECT_EQ(d.pos.line, 2u);
}

TEST(Datasheet, AMissingTemplateNamesWhereItWasSearched) {
    auto options = default_options();
    options.template_dirs = {"/nonexistent-templates"};
    const auto pages = esi::doc::render_datasheets(load(sample_esi()), "out", options);
    EXPECT_TRUE(pages.files.empty());
    ASSERT_TRUE(pages.diagnostics.has_errors());
    EXPECT_EQ(pages.diagnostics.items().front().rule, "doc-template-missing");
    EXPECT_NE(pages.diagnostics.items().front().message.find("/nonexistent-templates"), std::string::npos);
}

TEST(Datasheet, AModularDeviceShowsItsSlotsAndTheModulesTheyAccept) {
    const auto document = load(samples_dir() / "modular-coupler.yaml");
    const auto pages = render(document);
    const std::string& page = device_page(pages);
    EXPECT_NE(page.find("<section id=\"modules\">"), std::string::npos);
    for (const std::string module : {"EX-M-DI8", "EX-M-DO8", "EX-M-AI2"}) EXPECT_NE(page.find("Module " + module), std::string::npos) << module;
    EXPECT_NE(page.find("data-entry=\"m2:T0:1\""), std::string::npos);  // AI2's second input
}

TEST(Datasheet, DictionaryValuesAreShownAsTheirTypeReadsThem) {
    const auto pages = render(load(samples_dir() / "modular-coupler.yaml"));
    const std::string& page = device_page(pages);
    // 0xF000:01 Module index distance, UINT, default 16 (written 0x10 in the source).
    EXPECT_TRUE(std::regex_search(page, std::regex("<td>Module index distance</td><td>UINT</td><td class=\"num\">16</td><td>ro</td><td></td><td>16</td>")))
        << "row of 0xF000:01 not found";
}

TEST(Datasheet, MarkupInNamesStaysTextAndHugeBitLengthsStayCheap) {
    TempDir dir;
    std::string text = read_text(sample_esi());
    const auto replace = [&](const std::string& from, const std::string& to) {
        const std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace("<BitLen>8</BitLen>\n            <Name>Digital outputs</Name>",
            "<BitLen>4294967295</BitLen>\n            <Name>&lt;/svg&gt;&lt;script&gt;alert(1)&lt;/script&gt; &amp; \"q\"</Name>");
    write_text(dir / "hostile.xml", text);
    const auto start = std::chrono::steady_clock::now();
    const auto pages = render(load(dir / "hostile.xml"));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
    const std::string& page = device_page(pages);
    EXPECT_EQ(page.find("<script"), std::string::npos);
    EXPECT_NE(page.find("&lt;/svg&gt;&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;q&quot;"), std::string::npos);
    EXPECT_LT(page.size(), 200'000u);
}

TEST(Datasheet, FileNamesAreUniqueEvenWithoutCase) {
    esi::Device a, b, c, d;
    a.type.text = "EL1008";
    a.type.revision_no = 0x00100000;
    b = a;
    c.type.text = "el1008";
    c.type.revision_no = 0x00100000;
    d.type.text = "";
    EXPECT_EQ(esi::doc::page_file_names({&a, &b, &c, &d}),
              (std::vector<std::string>{"EL1008-rev00100000.html", "EL1008-rev00100000-2.html", "el1008-rev00100000-3.html", "device.html"}));
}

TEST(Datasheet, DictionaryAndModuleFilesGetAPageOfTheirOwn) {
    ESI_REQUIRE_CORPUS();
    const auto dict = render(load(esi::test::corpus_esi_dir() / "Beckhoff__AX5101-xxxx-0210_Dict__dls-ethercat.xml"));
    ASSERT_TRUE(dict.count("out/dictionary.html"));
    EXPECT_GT(occurrences(dict.at("out/dictionary.html"), "<tr"), 700u);
    const auto modules = render(load(esi::test::corpus_esi_dir() / "Beckhoff__BKxxxxModules__dls-ethercat__2013-03.xml"));
    ASSERT_TRUE(modules.count("out/modules.html"));
    EXPECT_NE(modules.at("out/modules.html").find("<section class=\"module\""), std::string::npos);
}

}  // namespace

namespace {

TEST(Datasheet, ReadsLikeADatasheetCountsEnumerationsAndDcFactors) {
    const auto pages = render(load(sample_esi()));
    const std::string& page = device_page(pages);
    // Counts in words, singular where it is one.
    EXPECT_EQ(page.find("1 bytes"), std::string::npos);
    EXPECT_EQ(page.find("1 commands"), std::string::npos);
    // CycleTimeSync0 Factor="1" with 0 ns: the factor spelled out.
    EXPECT_NE(page.find("<td>1 × the cycle</td>"), std::string::npos);
    EXPECT_EQ(page.find("0 ns × 1"), std::string::npos);
    EXPECT_NE(pages.at("out/index.html").find("1 device page from"), std::string::npos) << pages.at("out/index.html");
    // The index is titled by vendor and catalogue, not by the file.
    EXPECT_NE(pages.at("out/index.html").find("<title>&#x2068;Example Automation GmbH: Digital I/O&#x2069;</title>"), std::string::npos)
        << pages.at("out/index.html");
}

}  // namespace
