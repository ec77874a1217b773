// esi-doc's pages, esi-diff's HTML report and esi-net's process-image page in a real browser: headless Chromium, driven over
// the DevTools protocol by tests/doc/page_facts.py (Python standard library only), which reports
// what the browser laid out and painted. Asserted here for every page, at 1280 px:
//   - no horizontal overflow;
//   - every bit-layout SVG has a non-zero box, a title, and a label for each of its entries;
//   - every PDO table has a box in its picture for each row;
//   - every PDO entry of the ESI has exactly one table row in its device's page;
//   - no console errors or warnings, no request leaves the page, no script;
//   - the screenshot is not blank, and the pictures' tints are painted in it.
// Chromium comes from Debian's `chromium` package (scripts/install-deps.sh --with-browser); the
// tests skip with a message where it or python3 is absent. ESI_CHROMIUM names another binary.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <map>
#include <optional>

#include "doc_test_support.hpp"
#include "esi/doc/datasheet.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using namespace esi::test::doc;

std::optional<std::string> chromium() {
    if (const char* env = std::getenv("ESI_CHROMIUM"); env && *env) return std::string(env);
    for (const char* name : {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable"}) {
        const auto r = run({"sh", "-c", std::string("command -v ") + name});
        if (r.exit_code == 0) return r.out.substr(0, r.out.find('\n'));
    }
    return std::nullopt;
}

#define ESI_REQUIRE_BROWSER()                                                                                      \
    const std::optional<std::string> browser = chromium();                                                         \
    if (!browser) GTEST_SKIP() << "no chromium on PATH (scripts/install-deps.sh --with-browser): browser test skipped"; \
    if (run({"sh", "-c", "command -v python3"}).exit_code != 0) GTEST_SKIP() << "no python3: browser test skipped"

// A page to check and, for a device page, the data-entry keys its PDO tables must hold.
struct Page {
    fs::path path;
    std::optional<std::vector<std::string>> entry_keys;
};

// Renders `source` with esi-doc into `out` and lists its pages; `keep` picks device pages (all
// when it is empty) by file name.
std::vector<Page> doc_pages(const fs::path& source, const fs::path& out, const std::vector<std::string>& keep = {}) {
    const auto r = esi_doc(source, out);
    EXPECT_EQ(r.exit_code, 0) << source << ": " << r.err;
    const esi::EsiDocument document = load(source);
    const auto devices = esi::select_devices(document, std::nullopt);
    const auto names = esi::doc::page_file_names(devices);
    std::vector<Page> pages{{out / "index.html", std::nullopt}};
    for (std::size_t i = 0; i < devices.size(); ++i)
        if (keep.empty() || std::find(keep.begin(), keep.end(), names[i]) != keep.end())
            pages.push_back({out / names[i], expected_entry_keys(document, *devices[i])});
    for (const char* extra : {"dictionary.html", "modules.html"})
        if (fs::exists(out / extra)) pages.push_back({out / extra, std::nullopt});
    return pages;
}

Page diff_page(const fs::path& old_path, const fs::path& new_path, const fs::path& out) {
    const auto r = run({tool("esi-diff").string(), old_path.string(), new_path.string(), "--format", "html"});
    EXPECT_NE(r.exit_code, 2) << r.err;
    esi::test::write_text(out, r.out);
    return {out, std::nullopt};
}

// What the pages add up to, for checks over a whole set (an enumeration shown somewhere).
struct PageTotals {
    int enum_texts = 0;
    int hex_cells = 0;
    int dc_factor_cells = 0;
};

PageTotals check_in_browser(const std::string& browser, const std::vector<Page>& pages, const TempDir& dir) {
    PageTotals totals;
    std::vector<std::string> argv{"python3", (esi::test::source_dir() / "tests" / "doc" / "page_facts.py").string(), "--chromium", browser,
                                  "--profile", (dir / "chromium-profile").string()};
    for (const Page& p : pages) argv.push_back(p.path.string());
    const auto r = run(argv);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    if (r.exit_code != 0) return totals;
    const Json facts = Json::parse(r.out);
    EXPECT_EQ(facts.size(), pages.size());
    if (facts.size() != pages.size()) return totals;
    for (std::size_t i = 0; i < pages.size(); ++i) {
        const Json& f = facts[i];
        const std::string name = pages[i].path.filename().string() + " (" + pages[i].path.parent_path().filename().string() + ")";
        SCOPED_TRACE(name);
        EXPECT_LE(f["scroll_width"].get<int>(), f["client_width"].get<int>()) << "horizontal overflow: " << f["wide_elements"].dump();
        EXPECT_EQ(f["client_width"].get<int>(), 1280);
        EXPECT_TRUE(f["console"].empty()) << f["console"].dump();
        EXPECT_TRUE(f["requests"].empty()) << f["requests"].dump();
        EXPECT_EQ(f["scripts"].get<int>(), 0);
        EXPECT_FALSE(f["title"].get<std::string>().empty());
        EXPECT_FALSE(f["lang"].get<std::string>().empty());
        // Hex where hex is meant, factors spelled out; an index page is titled by vendor and
        // catalogue, not by the file.
        EXPECT_TRUE(f["not_hex"].empty()) << "cells marked hex: " << f["not_hex"].dump();
        EXPECT_TRUE(f["dc_bare_factors"].empty()) << f["dc_bare_factors"].dump();
        if (pages[i].path.filename() == "index.html") {
            EXPECT_EQ(f["title"].get<std::string>().find(".xml"), std::string::npos) << f["title"];
            // The title holds the same text, inside a first-strong isolate (U+2068 … U+2069): a
            // <title> cannot hold <bdi>.
            std::string title = f["title"].get<std::string>();
            for (const std::string mark : {"\u2068", "\u2069"})
                for (std::size_t at = title.find(mark); at != std::string::npos; at = title.find(mark)) title.erase(at, mark.size());
            EXPECT_EQ(f["h1"].get<std::string>(), title);
        }
        totals.enum_texts += f["enum_texts"].get<int>();
        totals.hex_cells += f["hex_cells"].get<int>();
        totals.dc_factor_cells += f["dc_factor_cells"].get<int>();
        for (const Json& svg : f["svgs"]) {
            EXPECT_GT(svg["width"].get<double>(), 0) << svg["id"];
            EXPECT_GT(svg["height"].get<double>(), 0) << svg["id"];
            EXPECT_EQ(svg["unlabelled"].get<int>(), 0) << svg["id"];
            EXPECT_FALSE(svg["title"].get<std::string>().empty()) << svg["id"];
        }
        for (const Json& pdo : f["pdo_sections"]) EXPECT_EQ(pdo["rows"], pdo["entries"]) << "PDO " << pdo["id"];
        if (pages[i].entry_keys) {
            const auto& keys = *pages[i].entry_keys;
            for (const std::string& key : keys) EXPECT_EQ(f["entry_keys"].value(key, 0), 1) << "PDO entry " << key;
            EXPECT_EQ(f["entry_keys"].size(), keys.size());
        }
        const Json& shot = f["screenshot"];
        EXPECT_EQ(shot["width"].get<int>(), 320);
        EXPECT_GT(shot["colours"].get<int>(), 8) << "blank screenshot";
        if (!f["first_svg_top"].is_null()) {
            EXPECT_GE(shot["picture_tints"].get<int>(), 1) << "pictures laid out but not painted";
        }
    }
    return totals;
}

TEST(Browser, SamplePagesAndTheirHtmlDiffs) {
    ESI_REQUIRE_BROWSER();
    TempDir dir;
    std::vector<Page> pages;
    for (const fs::path& source : sample_sources()) {
        const auto more = doc_pages(source, dir / source.stem().string());
        pages.insert(pages.end(), more.begin(), more.end());
    }
    const fs::path data = esi::test::source_dir() / "tests" / "diff" / "data";
    pages.push_back(diff_page(data / "old.xml", data / "new.xml", dir / "diff.html"));
    // esi-net's process-image map of the sample line.
    const auto net = run({tool("esi-net").string(), "--no-cache", "build", (esi::test::source_dir() / "samples" / "networks" / "line.yaml").string(),
                          "-o", (dir / "line").string(), "--only", "html"});
    EXPECT_EQ(net.exit_code, 0) << net.err;
    pages.push_back({dir / "line" / "process_image.html", std::nullopt});
    const PageTotals totals = check_in_browser(*browser, pages, dir);
    // digital-io-8 has an enumeration (0x8000 input filter) and DC modes with a factor.
    EXPECT_GT(totals.enum_texts, 0);
    EXPECT_GT(totals.dc_factor_cells, 0);
    EXPECT_GT(totals.hex_cells, 0);
}

TEST(Browser, CorpusCataloguesDrivesAndModularDevices) {
    ESI_REQUIRE_CORPUS();
    ESI_REQUIRE_BROWSER();
    TempDir dir;
    const fs::path c = esi::test::corpus_esi_dir();
    std::vector<Page> pages;
    const auto add = [&](const std::vector<Page>& more) { pages.insert(pages.end(), more.begin(), more.end()); };
    add(doc_pages(c / "Beckhoff__EtherCAT_Terminals__dls-ethercat.xml", dir / "terminals"));  // 40 devices
    // SoE drives: the two-channel AX5203 (InitCmds, DC modes, dynamic PDOs) and a one-channel one;
    // the AX5101 dictionary file (757 objects).
    add(doc_pages(c / "Beckhoff__AX5xxx__dls-ethercat.xml", dir / "ax5xxx",
                  {"AX5203-0000-0210-rev00D20000.html", "AX5101-0000-0003-rev00030000.html"}));
    add(doc_pages(c / "Beckhoff__AX5101-xxxx-0210_Dict__dls-ethercat.xml", dir / "ax5101-dict"));
    // Modular devices: slots and the modules they accept.
    add(doc_pages(c / "ETG__ModulesSlots_CiA402__siitool.xml", dir / "etg-modular"));
    add(doc_pages(c / "Weidmueller__UR20_FBC__ethercat-esi.xml", dir / "ur20"));
    // The largest page of the EL3xxx catalogue (1,710 objects over 37 terminals): EL3632.
    add(doc_pages(c / "Beckhoff__EL3xxx__dls-ethercat.xml", dir / "el3xxx", {"EL3632-rev00160000.html"}));
    pages.push_back(diff_page(c / "MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-02.xml",
                              c / "MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-10.xml", dir / "easercat-diff.html"));
    pages.push_back(diff_page(c / "PollenRobotics__NeckOrbita3d_fw1.0__poulpe.xml", c / "PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml",
                              dir / "neck-diff.html"));
    const PageTotals totals = check_in_browser(*browser, pages, dir);
    // The EL3632 page and the AX5xxx drives: enumerations (DataType EnumInfo) and DC factors.
    EXPECT_GT(totals.enum_texts, 0);
    EXPECT_GT(totals.dc_factor_cells, 0);
    EXPECT_GT(totals.hex_cells, 1000);
}

}  // namespace
