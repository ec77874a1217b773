// XML 1.0 well-formedness on real files (issue 16): every XML file of ../shared/corpus (ESI files,
// ENI exports, master configurations, the ETG schemas) gets the verdict xmllint (libxml2) gives
// it: a file xmllint accepts reads without an xml-syntax error, a file it rejects is refused
// with xml-syntax or xml-encoding. Skipped where the corpus or xmllint is absent.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "esi/xml/reader.hpp"
#include "support/test_support.hpp"

namespace {

std::vector<std::filesystem::path> corpus_xml_files() {
    std::vector<std::filesystem::path> files;
    const auto corpus = esi::test::shared_dir() / "corpus";
    for (const auto& entry : std::filesystem::recursive_directory_iterator(corpus)) {
        const auto extension = entry.path().extension();
        if (entry.is_regular_file() && (extension == ".xml" || extension == ".xsd")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(CorpusWellFormedness, EveryFileGetsTheVerdictOfXmllint) {
    ESI_REQUIRE_CORPUS();
    if (esi::test::run({"sh", "-c", "command -v xmllint"}).exit_code != 0) GTEST_SKIP() << "xmllint not installed: comparison skipped";
    std::size_t accepted = 0;
    std::size_t rejected = 0;
    for (const auto& path : corpus_xml_files()) {
        SCOPED_TRACE(path.string());
        const bool xmllint_accepts = esi::test::run({"xmllint", "--noout", "--nonet", path.string()}).exit_code == 0;
        const esi::ReadResult read = esi::read_esi_file(path);
        const esi::Diagnostic* fault = nullptr;
        for (const auto& d : read.diagnostics)
            if ((d.rule == "xml-syntax" || d.rule == "xml-encoding") && !fault) fault = &d;
        if (xmllint_accepts) {
            ++accepted;
            EXPECT_EQ(fault, nullptr) << fault->rule << " " << fault->pos.line << ":" << fault->pos.column << " " << fault->message;
            EXPECT_TRUE(read.document.has_value());
        } else {
            ++rejected;
            EXPECT_NE(fault, nullptr) << "xmllint rejects the file, the reader accepts it";
        }
    }
    // 96 ESI files (two of them broken), 53 other XML files when this was written.
    EXPECT_GE(accepted, 140u);
    EXPECT_GE(rejected, 2u);
}

}  // namespace
