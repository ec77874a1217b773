// esi-lint over every real vendor file in ../shared/corpus/esi (skipped where it is absent):
// well-formed files read without xml-syntax and without a crash; the files MANIFEST.tsv marks
// NOT WELL-FORMED get their error at the line xmllint reports.

#include <gtest/gtest.h>

#include <regex>

#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace {

std::optional<std::uint32_t> xmllint_line(const std::string& notes) {
    static const std::regex line_re(R"(NOT WELL-FORMED: line (\d+))");
    std::smatch m;
    if (std::regex_search(notes, m, line_re)) return static_cast<std::uint32_t>(std::stoul(m[1].str()));
    return std::nullopt;
}

TEST(CorpusLint, EveryFileIsReadAndMalformedOnesAreLocated) {
    ESI_REQUIRE_CORPUS();
    const auto manifest = esi::test::corpus_manifest();
    ASSERT_FALSE(manifest.empty());
    std::size_t well_formed = 0;
    std::size_t malformed = 0;
    for (const auto& [file, notes] : manifest) {
        const auto path = esi::test::corpus_esi_dir() / file;
        if (path.extension() != ".xml" || !std::filesystem::exists(path)) continue;
        SCOPED_TRACE(file);
        const auto report = esi::lint_bytes(esi::test::read_text(path), path.string(), {});
        const esi::Diagnostic* syntax = nullptr;
        const esi::Diagnostic* encoding = nullptr;
        for (const auto& d : report.diagnostics) {
            if (d.rule == "xml-syntax" && !syntax) syntax = &d;
            if (d.rule == "xml-encoding" && !encoding) encoding = &d;
        }
        if (notes.find("NOT WELL-FORMED") == std::string::npos) {
            ++well_formed;
            EXPECT_EQ(syntax, nullptr) << syntax->message << " at line " << syntax->pos.line;
            EXPECT_EQ(encoding, nullptr);
        } else {
            ++malformed;
            const esi::Diagnostic* fault = syntax ? syntax : encoding;
            ASSERT_NE(fault, nullptr) << "malformed file read without xml-syntax or xml-encoding error";
            EXPECT_EQ(fault->severity, esi::Severity::error);
            if (const auto line = xmllint_line(notes)) {
                EXPECT_EQ(fault->pos.line, *line) << fault->message;
            }
        }
    }
    std::printf("corpus: %zu well-formed files read cleanly, %zu malformed files located\n", well_formed, malformed);
    EXPECT_GT(well_formed, 0u);
}

TEST(CorpusLint, WholeCorpusInParallelMatchesSequential) {
    ESI_REQUIRE_CORPUS();
    esi::LintOptions sequential;
    sequential.jobs = 1;
    esi::LintOptions parallel;
    parallel.jobs = 4;
    const auto a = esi::lint_paths({esi::test::corpus_esi_dir()}, sequential);
    const auto b = esi::lint_paths({esi::test::corpus_esi_dir()}, parallel);
    ASSERT_EQ(a.files.size(), b.files.size());
    for (std::size_t i = 0; i < a.files.size(); ++i) {
        ASSERT_EQ(a.files[i].path, b.files[i].path);
        ASSERT_EQ(a.files[i].diagnostics.size(), b.files[i].diagnostics.size()) << a.files[i].path;
        for (std::size_t k = 0; k < a.files[i].diagnostics.size(); ++k)
            EXPECT_EQ(a.files[i].diagnostics.items()[k].message, b.files[i].diagnostics.items()[k].message);
    }
}

}  // namespace
