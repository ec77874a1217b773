// Hostile and broken ESI XML (issue 6 §2): each case gets a located diagnostic, a defined exit
// code from esi-lint, bounded memory (peak RSS of the child, bounds in docs/reliability.md) and
// no crash. Time is bounded by the ctest TIMEOUT, never asserted.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>

#include "esi/lint/lint.hpp"
#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"
#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::Listener;
using esi::test::memory_scale;
using esi::test::run_child;
using esi::test::sample_esi;

constexpr const char* vendor_name = "<Name LcId=\"1033\">Example Automation GmbH</Name>";

std::string lint_tool() { return esi::test::tool("esi-lint").string(); }

const esi::Diagnostic* find(const esi::Diagnostics& diagnostics, std::string_view rule) {
    for (const auto& d : diagnostics)
        if (d.rule == rule) return &d;
    return nullptr;
}

// The sample with a DOCTYPE after the XML declaration.
std::string with_doctype(const std::string& doctype, const std::string& vendor_name_text) {
    std::string text = sample_esi();
    const auto declaration_end = text.find("?>") + 2;
    text.insert(declaration_end, "\n" + doctype);
    return esi::test::replace_once(text, vendor_name, "<Name LcId=\"1033\">" + vendor_name_text + "</Name>");
}

std::string billion_laughs() {
    std::string doctype = "<!DOCTYPE EtherCATInfo [\n<!ENTITY lol0 \"lol\">\n";
    for (int i = 1; i <= 9; ++i) {
        doctype += "<!ENTITY lol" + std::to_string(i) + " \"";
        for (int k = 0; k < 10; ++k) doctype += "&lol" + std::to_string(i - 1) + ";";
        doctype += "\">\n";
    }
    doctype += "]>";
    return with_doctype(doctype, "&lol9;");
}

const esi::Vendor& vendor_of(const esi::ReadResult& read) {
    return *read.document->infos.at(0).vendor;
}

}  // namespace

TEST(HostileXml, EntityBombIsNeitherExpandedNorRejected) {
    const std::string text = billion_laughs();
    const esi::ReadResult read = esi::read_esi(text, "bomb.xml");
    ASSERT_TRUE(read.document);
    EXPECT_EQ(vendor_of(read).names.at(0).text, "&lol9;") << "the reference must stay as written";
    const esi::Diagnostic* doctype = find(read.diagnostics, "xml-doctype");
    ASSERT_NE(doctype, nullptr);
    EXPECT_EQ(doctype->severity, esi::Severity::warning);
    EXPECT_EQ(doctype->pos.line, 2u);
    EXPECT_EQ(doctype->pos.column, 1u);
    EXPECT_NE(doctype->message.find("not expanded"), std::string::npos);

    esi::test::TempDir dir;
    esi::test::write_text(dir / "bomb.xml", text);
    const auto lint = run_child({lint_tool(), "--fail-on", "warning", (dir / "bomb.xml").string()});
    EXPECT_EQ(lint.exit_code, 1) << lint.err;
    EXPECT_NE(lint.out.find("bomb.xml:2:1: warning:"), std::string::npos) << lint.out;
    EXPECT_LT(lint.max_rss_kb, 64 * 1024 * memory_scale());
}

TEST(HostileXml, EntityBombIsNotExpandedBySchemaValidation) {
    ESI_REQUIRE_CORPUS();
    esi::test::TempDir dir;
    esi::test::write_text(dir / "bomb.xml", billion_laughs());
    const auto schema = esi::test::shared_dir() / "corpus" / "schema" / "v1.17_siitool-2022";
    const auto lint = run_child({lint_tool(), "--xsd", schema.string(), (dir / "bomb.xml").string()});
    // A tree with entity references is not validated (nothing expands them), and says so.
    EXPECT_EQ(lint.exit_code, 1) << lint.out << lint.err;
    EXPECT_NE(lint.out.find("not validated against the schema: the document uses entity references"), std::string::npos) << lint.out;
    EXPECT_NE(lint.out.find("[xml-schema]"), std::string::npos) << lint.out;
    EXPECT_EQ(lint.err, "");
    EXPECT_EQ(lint.out.find("lollol"), std::string::npos);
    EXPECT_LT(lint.max_rss_kb, 64 * 1024 * memory_scale());
}

TEST(HostileXml, ExternalEntitiesAreNeverFetched) {
    esi::test::TempDir dir;
    const std::string secret = "SECRET-7f3a9c-not-for-output";
    esi::test::write_text(dir / "secret.txt", secret);
    Listener listener;
    const std::string url = "http://127.0.0.1:" + std::to_string(listener.port());
    const std::string text = with_doctype("<!DOCTYPE EtherCATInfo SYSTEM \"" + url + "/EtherCATInfo.dtd\" [\n"
                                          "<!ENTITY file SYSTEM \"file://" + (dir / "secret.txt").string() + "\">\n"
                                          "<!ENTITY net SYSTEM \"" + url + "/entity\">\n]>",
                                          "&file;&net;");
    esi::test::write_text(dir / "xxe.xml", text);

    const esi::ReadResult read = esi::read_esi(text, "xxe.xml");
    ASSERT_TRUE(read.document);
    EXPECT_EQ(vendor_of(read).names.at(0).text, "&file;&net;");
    ASSERT_NE(find(read.diagnostics, "xml-doctype"), nullptr);

    std::vector<std::vector<std::string>> runs = {{lint_tool(), (dir / "xxe.xml").string()},
                                                  {lint_tool(), "--format", "json", (dir / "xxe.xml").string()}};
    if (esi::test::have_shared_corpus())
        runs.push_back({lint_tool(), "--xsd", (esi::test::shared_dir() / "corpus/schema/v1.17_siitool-2022").string(),
                        (dir / "xxe.xml").string()});
    for (const auto& argv : runs) {
        const auto lint = run_child(argv);
        EXPECT_TRUE(lint.exit_code == 0 || lint.exit_code == 1) << lint.err;
        EXPECT_EQ(lint.out.find(secret), std::string::npos) << "a local file was read into the output";
        EXPECT_EQ(lint.err.find(secret), std::string::npos);
    }
    EXPECT_FALSE(listener.anyone_connected()) << "an external entity or DTD was fetched over the network";
}

TEST(HostileXml, HundredThousandDeepNestingIsCutWithADiagnostic) {
    std::string text = "<?xml version=\"1.0\"?>\n<EtherCATInfo>\n";
    text.reserve(1'000'000);
    for (int i = 0; i < 100'000; ++i) text += "<a>";
    for (int i = 0; i < 100'000; ++i) text += "</a>";
    text += "\n</EtherCATInfo>\n";
    const esi::ReadResult read = esi::read_esi(text, "deep.xml");
    ASSERT_TRUE(read.document);
    const esi::Diagnostic* depth = find(read.diagnostics, "xml-nesting-depth");
    ASSERT_NE(depth, nullptr);
    EXPECT_EQ(depth->pos.line, 3u);
    EXPECT_EQ(depth->pos.column, 1u + 3u * 255u) << "the first element that is not kept (depth 256)";
    // The writer and the rules get the cut tree, never the 100,000 levels.
    const std::string written = esi::write_esi(*read.document);
    std::size_t levels = 0;
    for (auto at = written.find("<a>"); at != std::string::npos; at = written.find("<a>", at + 1)) ++levels;
    EXPECT_EQ(levels, 255u) << "the kept levels below EtherCATInfo";
    (void)esi::run_rules(*read.document, esi::EffectiveConfig{});

    esi::test::TempDir dir;
    esi::test::write_text(dir / "deep.xml", text);
    const auto lint = run_child({lint_tool(), "--format", "json", (dir / "deep.xml").string()});
    EXPECT_EQ(lint.exit_code, 1) << lint.err;
    EXPECT_NE(lint.out.find("xml-nesting-depth"), std::string::npos);
    EXPECT_LT(lint.max_rss_kb, 128 * 1024 * memory_scale());
}

TEST(HostileXml, DeepNestingInsideTheDictionaryIsBounded) {
    // Object/Info/SubItem/Info/SubItem… is the one typed element the reader follows recursively.
    std::string nested;
    for (int i = 0; i < 50'000; ++i) nested += "<SubItem><Info>";
    for (int i = 0; i < 50'000; ++i) nested += "</Info></SubItem>";
    const std::string text = esi::test::replace_once(sample_esi(), "<Index>#x1000</Index>",
                                                     "<Index>#x1000</Index><Info>" + nested + "</Info>");
    const esi::ReadResult read = esi::read_esi(text, "deep-od.xml");
    ASSERT_TRUE(read.document);
    const esi::Diagnostic* depth = find(read.diagnostics, "xml-nesting-depth");
    ASSERT_NE(depth, nullptr);
    EXPECT_EQ(depth->pos.line, esi::test::line_of(text, "<Index>#x1000</Index>"));
    (void)esi::write_esi(*read.document);
    (void)esi::run_rules(*read.document, esi::EffectiveConfig{});
}

TEST(HostileXml, FiftyMegabyteAttributeIsQuotedShortly) {
    const std::size_t size = 50u << 20;
    const std::string text =
        esi::test::replace_once(sample_esi(), "ProductCode=\"#x00001001\"", "ProductCode=\"" + std::string(size, '9') + "\"");
    {
        const esi::ReadResult read = esi::read_esi(text, "big.xml");
        ASSERT_TRUE(read.document);
        const esi::Diagnostic* number = find(read.diagnostics, "xml-number-format");
        ASSERT_NE(number, nullptr);
        EXPECT_EQ(number->pos.line, esi::test::line_of(text, "<Type ProductCode="));
        EXPECT_LT(number->message.size(), 300u) << "the value is quoted as an excerpt";
        EXPECT_NE(number->message.find("(52428800 bytes)"), std::string::npos) << number->message;
    }
    esi::test::TempDir dir;
    esi::test::write_text(dir / "big.xml", text);
    for (const std::string format : {"text", "json", "sarif"}) {
        const auto lint = run_child({lint_tool(), "--format", format, (dir / "big.xml").string()});
        EXPECT_EQ(lint.exit_code, 1) << format << ": " << lint.err;
        EXPECT_NE(lint.out.find("xml-number-format"), std::string::npos) << format;
        EXPECT_EQ(lint.out.find(std::string(1000, '9')), std::string::npos) << format << ": the output must not carry the value";
        EXPECT_LT(lint.out.size(), 1u << 20) << format;
        // Bound: 8 times the input (decoded text, DOM, the quoted line) plus 64 MB.
        EXPECT_LT(lint.max_rss_kb, static_cast<long>((8 * size >> 10) + 64 * 1024) * memory_scale()) << format;
    }
}

TEST(HostileXml, NulByteIsASyntaxErrorAtItsPosition) {
    std::string text = sample_esi();
    const auto at = text.find("Example Automation GmbH");
    const std::uint32_t line = esi::test::line_of(text, "Example Automation GmbH");
    text[at + 7] = '\0';
    const esi::ReadResult read = esi::read_esi(text, "nul.xml");
    EXPECT_FALSE(read.document);
    const esi::Diagnostic* syntax = find(read.diagnostics, "xml-syntax");
    ASSERT_NE(syntax, nullptr);
    EXPECT_EQ(syntax->pos.line, line);
    EXPECT_EQ(syntax->pos.column, static_cast<std::uint32_t>(at + 7 - text.rfind('\n', at)));
    EXPECT_NE(syntax->message.find("NUL"), std::string::npos);

    esi::test::TempDir dir;
    esi::test::write_text(dir / "nul.xml", text);
    const auto lint = run_child({lint_tool(), (dir / "nul.xml").string()});
    EXPECT_EQ(lint.exit_code, 1);
    EXPECT_NE(lint.out.find("nul.xml:" + std::to_string(syntax->pos.line) + ":"), std::string::npos) << lint.out;
}

TEST(HostileXml, InvalidUtf8IsAnEncodingErrorAtTheBadByte) {
    const std::string text = esi::test::replace_once(sample_esi(), "Example Automation", "Example \xC3\x28utomation");
    const esi::ReadResult read = esi::read_esi(text, "bad-utf8.xml");
    ASSERT_TRUE(read.document) << "bad bytes are replaced and reading goes on";
    const esi::Diagnostic* encoding = find(read.diagnostics, "xml-encoding");
    ASSERT_NE(encoding, nullptr);
    EXPECT_EQ(encoding->severity, esi::Severity::error);
    EXPECT_EQ(encoding->pos.line, esi::test::line_of(text, "Example \xC3"));
    EXPECT_EQ(encoding->pos.column, 31u) << "the column of the bad byte in '    <Name LcId=\"1033\">Example '";

    esi::test::TempDir dir;
    esi::test::write_text(dir / "bad-utf8.xml", text);
    const auto lint = run_child({lint_tool(), (dir / "bad-utf8.xml").string()});
    EXPECT_EQ(lint.exit_code, 1);
    EXPECT_NE(lint.out.find("[xml-encoding]"), std::string::npos);
}

TEST(HostileXml, Utf16WithALoneSurrogateIsAnEncodingError) {
    // The sample as UTF-16LE with a BOM; the vendor name gets an unpaired high surrogate.
    const std::string utf8 = esi::test::replace_once(sample_esi(), "encoding=\"UTF-8\"", "encoding=\"UTF-16\"");
    std::u16string units;
    for (std::size_t i = 0; i < utf8.size();) {
        const auto c = static_cast<unsigned char>(utf8[i]);
        char32_t cp = c;
        std::size_t n = 1;
        if (c >= 0xF0) cp = c & 0x07, n = 4;
        else if (c >= 0xE0) cp = c & 0x0F, n = 3;
        else if (c >= 0xC0) cp = c & 0x1F, n = 2;
        for (std::size_t k = 1; k < n; ++k) cp = (cp << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
        i += n;
        if (utf8.compare(i - n, 7, "Example") == 0 && utf8.compare(i - n, 18, "Example Automation") == 0)
            units.push_back(u'\xD800');  // lone high surrogate before the vendor name
        if (cp >= 0x10000) {
            units.push_back(static_cast<char16_t>(0xD800 + ((cp - 0x10000) >> 10)));
            units.push_back(static_cast<char16_t>(0xDC00 + ((cp - 0x10000) & 0x3FF)));
        } else {
            units.push_back(static_cast<char16_t>(cp));
        }
    }
    std::string bytes = "\xFF\xFE";
    for (const char16_t u : units) {
        bytes.push_back(static_cast<char>(u & 0xFF));
        bytes.push_back(static_cast<char>(u >> 8));
    }
    const esi::ReadResult read = esi::read_esi(bytes, "utf16.xml");
    ASSERT_TRUE(read.document);
    const esi::Diagnostic* encoding = find(read.diagnostics, "xml-encoding");
    ASSERT_NE(encoding, nullptr);
    EXPECT_EQ(encoding->pos.line, esi::test::line_of(utf8, "Example Automation"));
    EXPECT_NE(encoding->message.find("UTF-16"), std::string::npos);

    esi::test::TempDir dir;
    esi::test::write_text(dir / "utf16.xml", bytes);
    const auto lint = run_child({lint_tool(), (dir / "utf16.xml").string()});
    EXPECT_EQ(lint.exit_code, 1);
    EXPECT_NE(lint.out.find("[xml-encoding]"), std::string::npos);
}

namespace {

// Every 1/16 of a file: a document or an xml-syntax error inside the truncated text, never more.
void expect_truncations_are_reported(const std::string& name, const std::string& text) {
    for (int k = 1; k < 16; ++k) {
        const std::string cut = text.substr(0, text.size() * k / 16);
        const esi::FileReport report = esi::lint_bytes(cut, name, esi::EffectiveConfig{});
        const auto lines = static_cast<std::uint32_t>(std::count(cut.begin(), cut.end(), '\n') + 1);
        const esi::Diagnostic* syntax = find(report.diagnostics, "xml-syntax");
        const esi::Diagnostic* encoding = find(report.diagnostics, "xml-encoding");
        ASSERT_TRUE(syntax || encoding) << name << " cut at " << k << "/16 gives no syntax or encoding error";
        const esi::Diagnostic* located = syntax ? syntax : encoding;
        EXPECT_TRUE(located->pos.known()) << name << " " << k << "/16";
        EXPECT_LE(located->pos.line, lines) << name << " " << k << "/16";
    }
}

}  // namespace

TEST(HostileXml, SampleTruncatedAtEverySixteenth) { expect_truncations_are_reported("sample", sample_esi()); }

TEST(HostileXml, CorpusFilesTruncatedAtEverySixteenth) {
    ESI_REQUIRE_CORPUS();
    // Different vendors, encodings and sizes: UTF-8 with BOM, ISO-8859-1, a dictionary, modules.
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(esi::test::corpus_esi_dir()))
        if (entry.path().extension() == ".xml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 6u);
    // Six files spread over the sorted list (deterministic, different vendors).
    for (std::size_t i = 0; i < 6; ++i) {
        const auto& file = files[i * (files.size() - 1) / 5];
        const std::string text = esi::test::read_text(file);
        if (text.size() > (4u << 20)) continue;  // keep the test quick; big files are fuzz seeds
        expect_truncations_are_reported(file.filename().string(), text);
    }
    // And through the tool: a cut file is exit code 1, not a crash or a usage error.
    esi::test::TempDir dir;
    const std::string text = esi::test::read_text(files.front());
    esi::test::write_text(dir / "cut.xml", text.substr(0, text.size() / 2));
    EXPECT_EQ(run_child({lint_tool(), (dir / "cut.xml").string()}).exit_code, 1);
}

TEST(HostileXml, ADirectoryIsAnIoErrorNotACrash) {
    esi::test::TempDir dir;
    std::filesystem::create_directories(dir / "trap.xml");
    const esi::ReadResult read = esi::read_esi_file(dir / "trap.xml");
    EXPECT_FALSE(read.document);
    const esi::Diagnostic* io = find(read.diagnostics, "io-error");
    ASSERT_NE(io, nullptr);
    EXPECT_NE(io->message.find("directory"), std::string::npos);
    // A directory named like a file is searched, not read; holding no ESI file, it is a usage
    // error (docs/esi-lint.md: an empty walk must not pass CI), not a crash.
    const auto lint = run_child({lint_tool(), (dir / "trap.xml").string()});
    EXPECT_EQ(lint.exit_code, 2) << lint.out << lint.err;
    EXPECT_NE(lint.out.find("no ESI files (*.xml) in this directory"), std::string::npos) << lint.out;
}

TEST(HostileXml, AnUnreadableFileIsExitCodeTwo) {
    // A file read() fails on, even for root: /proc/self/mem at offset 0 is unmapped (EIO).
    if (std::filesystem::exists("/proc/self/mem")) {
        const esi::ReadResult read = esi::read_esi_file("/proc/self/mem");
        EXPECT_FALSE(read.document);
        ASSERT_NE(find(read.diagnostics, "io-error"), nullptr);
        const auto lint = run_child({lint_tool(), "/proc/self/mem"});
        EXPECT_EQ(lint.exit_code, 2) << lint.out << lint.err;
        EXPECT_NE(lint.out.find("[io-error]"), std::string::npos) << lint.out;
    }
    if (!esi::test::permissions_apply())
        GTEST_SKIP() << "running as root: chmod 000 does not prevent reading, so that half is skipped "
                        "(the /proc/self/mem half ran)";
    esi::test::TempDir dir;
    esi::test::write_text(dir / "locked.xml", sample_esi());
    std::filesystem::permissions(dir / "locked.xml", std::filesystem::perms::none);
    const esi::ReadResult read = esi::read_esi_file(dir / "locked.xml");
    EXPECT_FALSE(read.document);
    const esi::Diagnostic* io = find(read.diagnostics, "io-error");
    ASSERT_NE(io, nullptr);
    EXPECT_NE(io->message.find("ermission"), std::string::npos) << io->message;
    const auto lint = run_child({lint_tool(), (dir / "locked.xml").string()});
    EXPECT_EQ(lint.exit_code, 2);
}

TEST(HostileXml, AZeroByteFileHasNoRootElement) {
    const esi::ReadResult read = esi::read_esi("", "empty.xml");
    EXPECT_FALSE(read.document);
    const esi::Diagnostic* syntax = find(read.diagnostics, "xml-syntax");
    ASSERT_NE(syntax, nullptr);
    EXPECT_EQ(syntax->pos.line, 1u);
    EXPECT_EQ(syntax->pos.column, 1u);
    esi::test::TempDir dir;
    esi::test::write_text(dir / "empty.xml", "");
    const auto lint = run_child({lint_tool(), (dir / "empty.xml").string()});
    EXPECT_EQ(lint.exit_code, 1);
    EXPECT_NE(lint.out.find("empty.xml:1:1: error: not well-formed: no root element [xml-syntax]"), std::string::npos) << lint.out;
}

TEST(HostileXml, AnEndlessStdinIsCutAtTheInputLimit) {
    esi::test::ChildOptions options;
    options.stdin_file = "/dev/zero";
    const auto lint = run_child({lint_tool(), "-"}, options);
    EXPECT_EQ(lint.exit_code, 2) << lint.err;
    EXPECT_NE(lint.out.find("<stdin>: error: cannot read: larger than 256 MiB"), std::string::npos) << lint.out;
    // Bound: the 256 MiB input limit, plus the growth of the buffer that holds it, plus 64 MB.
    EXPECT_LT(lint.max_rss_kb, (2 * 256 + 64) * 1024 * memory_scale());
}

TEST(HostileXml, AnEndlessFileIsCutAtTheInputLimit) {
    const esi::ReadResult read = esi::read_esi_file("/dev/zero");
    EXPECT_FALSE(read.document);
    ASSERT_NE(find(read.diagnostics, "io-error"), nullptr);
    EXPECT_NE(find(read.diagnostics, "io-error")->message.find("input size limit"), std::string::npos);
}
