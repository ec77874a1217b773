// docs/esi-doc.md, "The page view", against the views the templates see: the field tables there
// must list exactly the fields of the views built for real files, object by object. A field added
// to a view without a line in the docs, or a documented field that no view has, fails the test.
//
// The views are walked as built (doc/page_views.hpp, doc/diff_view.hpp), over the samples and the
// diff test data always, and over corpus files that have what the samples lack (InitCmds, slots,
// dictionary and module files) when ../shared is present. Without the corpus only "no
// undocumented field" is checked: the samples alone do not fill every list. A third test checks
// that the shipped templates use only documented fields.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "doc/diff_view.hpp"
#include "doc/page_views.hpp"
#include "doc/process_image_view.hpp"
#include "doc_test_support.hpp"
#include "esi/net/network.hpp"

namespace {

namespace fs = std::filesystem;
using esi::codegen::ViewValue;
using esi::doc::PageKind;
using namespace esi::test::doc;

// Object path ("" for the root, "device.pdos[]", "devices[]") -> the keys of that object.
using Fields = std::map<std::string, std::set<std::string>>;
// Page ("device", "index", "diff") -> its fields.
using PageFields = std::map<std::string, Fields>;

void collect(const ViewValue& value, const std::string& path, Fields& out) {
    if (value.is_object()) {
        auto& keys = out[path];
        for (const auto* m = value.begin_members(); m != value.end_members(); ++m) {
            keys.insert(std::string(m->key));
            collect(m->value, path.empty() ? std::string(m->key) : path + "." + std::string(m->key), out);
        }
    } else if (value.is_list()) {
        for (const auto* item = value.begin_items(); item != value.end_items(); ++item) collect(*item, path + "[]", out);
    }
}

void collect_pages(const esi::EsiDocument& document, PageFields& out) {
    const esi::doc::PagePlan plan = esi::doc::plan_pages(document, std::nullopt);
    esi::doc::build_page_views(document, plan, "out", esi::default_lcid, "css", [&](PageKind kind, const fs::path&, const ViewValue& root) {
        collect(root, "", out[kind == PageKind::device ? "device" : "index"]);
    });
}

void collect_diff(const fs::path& old_path, const fs::path& new_path, PageFields& out) {
    esi::DiffOptions options;
    options.keep_documents = true;
    const esi::FileDiff diff = esi::diff_files(old_path, new_path, options);
    ASSERT_TRUE(diff.result && diff.old_document && diff.new_document) << old_path;
    esi::codegen::ViewArena arena;
    const ViewValue view = esi::doc::diff_view(arena, *diff.old_document, *diff.new_document, *diff.result,
                                               {old_path.string(), new_path.string()}, esi::default_lcid, "css");
    collect(view, "", out["diff"]);
}

// esi-net's process-image page of samples/networks/line.yaml.
void collect_process_image(PageFields& out) {
    const esi::net::NetworkFileResult read =
        esi::net::read_network_file((esi::test::source_dir() / "samples" / "networks" / "line.yaml").string());
    ASSERT_TRUE(read.spec);
    const esi::net::BuildResult built = esi::net::build_network(*read.spec, esi::net::BuildOptions{});
    ASSERT_TRUE(built.network);
    esi::codegen::ViewArena arena;
    collect(esi::doc::process_image_view(arena, *built.network, "css"), "", out["process-image"]);
}

// The field tables of docs/esi-doc.md: under a heading "### ... page" naming the page (device,
// index, diff, process-image), a heading "#### The root" or "#### `path`, `path` …" starts the objects whose
// fields are the rows "| `key` | … |" of the table that follows (objects of one shape share it).
PageFields documented_fields() {
    std::ifstream in(esi::test::source_dir() / "docs" / "esi-doc.md");
    EXPECT_TRUE(in) << "docs/esi-doc.md missing";
    const std::regex page_heading(R"(^### .*\b(device|index|diff|process-image) page)", std::regex::icase);
    const std::regex path_in_heading("`([^`]*)`");
    const std::regex row(R"(^\| `([a-z_0-9]+)` \|)");
    PageFields out;
    std::string page;
    std::vector<std::string> objects;
    std::string line;
    std::smatch m;
    while (std::getline(in, line)) {
        if (line.starts_with("## ")) page.clear(), objects.clear();
        if (std::regex_search(line, m, page_heading)) {
            page = m[1].str();
            for (char& c : page) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            out[page];
            objects.clear();
        } else if (!page.empty() && line.starts_with("#### ")) {
            objects.clear();
            if (line == "#### The root") objects.emplace_back();
            for (auto it = std::sregex_iterator(line.begin(), line.end(), path_in_heading); it != std::sregex_iterator(); ++it)
                objects.push_back((*it)[1].str());
            for (const auto& o : objects) out[page][o];
        } else if (std::regex_search(line, m, row)) {
            for (const auto& o : objects)
                EXPECT_TRUE(out[page][o].insert(m[1].str()).second) << page << " page, `" << o << "`: " << m[1] << " listed twice";
        }
    }
    return out;
}

std::string describe(const std::set<std::string>& keys) {
    std::string out;
    for (const auto& k : keys) out += (out.empty() ? "" : ", ") + k;
    return out;
}

// Fields of `seen` missing from `listed`, object by object.
std::map<std::string, std::set<std::string>> missing(const Fields& seen, const Fields& listed) {
    std::map<std::string, std::set<std::string>> out;
    for (const auto& [path, keys] : seen) {
        const auto it = listed.find(path);
        for (const auto& k : keys)
            if (it == listed.end() || !it->second.contains(k)) out[path].insert(k);
    }
    return out;
}

PageFields walked_views(bool with_corpus) {
    PageFields seen;
    for (const fs::path& source : sample_sources()) collect_pages(load(source), seen);
    const fs::path data = esi::test::source_dir() / "tests" / "diff" / "data";
    collect_diff(data / "old.xml", data / "new.xml", seen);
    collect_process_image(seen);
    if (with_corpus) {
        const fs::path c = esi::test::corpus_esi_dir();
        for (const char* file : {"Beckhoff__AX5xxx__dls-ethercat.xml", "Beckhoff__AX5101-xxxx-0210_Dict__dls-ethercat.xml",
                                 "ETG__ModulesSlots_CiA402__siitool.xml", "Weidmueller__UR20_FBC__ethercat-esi.xml",
                                 "Beckhoff__BKxxxxModules__dls-ethercat__2013-03.xml"})
            collect_pages(load(c / file), seen);
        collect_diff(c / "MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-02.xml",
                     c / "MetalMusings__EaserCAT_7000__MyOwnEtherCATDevice__2025-10.xml", seen);
    }
    return seen;
}

TEST(DocViewFields, EveryFieldOfThePageViewsIsDocumented) {
    const PageFields listed = documented_fields();
    for (const auto& [page, fields] : walked_views(esi::test::have_shared_corpus())) {
        SCOPED_TRACE(page + " page");
        const auto it = listed.find(page);
        ASSERT_TRUE(it != listed.end()) << "docs/esi-doc.md has no field tables for the " << page << " page";
        for (const auto& [path, keys] : missing(fields, it->second))
            ADD_FAILURE() << "`" << (path.empty() ? "The root" : path) << "`: not in docs/esi-doc.md: " << describe(keys);
    }
}

TEST(DocViewFields, EveryDocumentedFieldIsInTheViews) {
    ESI_REQUIRE_CORPUS();
    const PageFields listed = documented_fields();
    const PageFields seen = walked_views(true);
    for (const auto& [page, fields] : listed) {
        SCOPED_TRACE(page + " page");
        const auto it = seen.find(page);
        ASSERT_TRUE(it != seen.end()) << "no view of the " << page << " page was built";
        for (const auto& [path, keys] : missing(fields, it->second))
            ADD_FAILURE() << "`" << (path.empty() ? "The root" : path) << "`: documented but in no view: " << describe(keys);
    }
}

// Every name the shipped templates use is a documented field of their page, so a template cannot
// rely on a field the docs (and so the views) do not have.
TEST(DocViewFields, TheShippedTemplatesUseOnlyDocumentedFields) {
    const PageFields listed = documented_fields();
    const std::regex tag(R"(\{\{\{?\s*[#^/&]?\s*([A-Za-z_][A-Za-z0-9_.]*)\s*\}?\}\})");
    for (const auto& [file, page] : std::map<std::string, std::string>{
             {"device.html.mustache", "device"}, {"index.html.mustache", "index"}, {"diff.html.mustache", "diff"},
             {"process_image.html.mustache", "process-image"}}) {
        SCOPED_TRACE(file);
        std::set<std::string> fields;
        for (const auto& [path, keys] : listed.at(page)) fields.insert(keys.begin(), keys.end());
        const std::string text = esi::test::read_text(esi::test::source_dir() / "templates" / "doc" / file);
        std::set<std::string> used;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), tag); it != std::sregex_iterator(); ++it) used.insert((*it)[1].str());
        EXPECT_GT(used.size(), 10u);
        for (const std::string& name : used) {
            std::string segment;
            std::istringstream parts(name);
            while (std::getline(parts, segment, '.')) EXPECT_TRUE(fields.contains(segment)) << "{{" << name << "}}: not a documented field";
        }
    }
}

}  // namespace
