// Numbers everywhere (issue 6 §2): `#x` without digits, values past 64 bits, values past their
// field, negative sizes, BitLen 0 and 65536. Each is a located diagnostic from the reader or a
// rule, esi-lint exits 1, and no number reaches the model as a silently wrapped value; the SII
// builder refuses a BitLen its one-byte field cannot hold.

#include <gtest/gtest.h>

#include "esi/lint/lint.hpp"
#include "esi/xml/reader.hpp"
#include "hostile/hostile_support.hpp"
#include "support/test_support.hpp"

namespace {

struct NumberCase {
    const char* name;
    const char* from;  // text of the sample that is replaced
    const char* to;
    const char* rule;  // the diagnostic expected on the line of `to`
    const char* message_part;
};

const NumberCase cases[] = {
    {"hex prefix without digits (attribute)", "ProductCode=\"#x00001001\"", "ProductCode=\"#x\"", "xml-number-format",
     "hex prefix without digits"},
    {"hex prefix without digits (element)", "<Index>#x7000</Index>", "<Index>#x</Index>", "xml-number-format",
     "hex prefix without digits"},
    {"hex past 64 bits", "RevisionNo=\"#x00010000\"", "RevisionNo=\"#x10000000000000000\"", "xml-number-format",
     "does not fit in 64 bits"},
    {"decimal past 64 bits", "<Id>#x00000E4A</Id>", "<Id>18446744073709551616</Id>", "xml-number-format",
     "does not fit in 64 bits"},
    {"past 32 bits", "<Id>#x00000E4A</Id>", "<Id>#x100000000</Id>", "xml-number-range", "out of range"},
    {"negative SM size", "DefaultSize=\"128\"", "DefaultSize=\"-1\"", "xml-number-range", "out of range"},
    {"negative EEPROM size", "<ByteSize>2048</ByteSize>", "<ByteSize>-2048</ByteSize>", "xml-number-range", "out of range"},
    {"negative BitSize", "<BitSize>144</BitSize>", "<BitSize>-144</BitSize>", "xml-number-range", "out of range"},
    {"negative BitLen", "<BitLen>8</BitLen>", "<BitLen>-8</BitLen>", "xml-number-range", "out of range"},
    {"BitLen 0", "<BitLen>8</BitLen>", "<BitLen>0</BitLen>", "pdo-mapping-limits", "has BitLen 0"},
    {"BitLen 65536", "<BitLen>8</BitLen>", "<BitLen>65536</BitLen>", "pdo-mapping-limits", "has BitLen 65536"},
};

}  // namespace

TEST(HostileNumbers, EveryMalformedNumberIsALocatedError) {
    for (const auto& c : cases) {
        const std::string text = esi::test::replace_once(esi::test::sample_esi(), c.from, c.to);
        const esi::FileReport report = esi::lint_bytes(text, "numbers.xml", esi::EffectiveConfig{});
        const auto line = esi::test::line_of(text, c.to);
        bool found = false;
        for (const auto& d : report.diagnostics)
            if (d.rule == c.rule && d.pos.line == line && d.message.find(c.message_part) != std::string::npos) found = true;
        EXPECT_TRUE(found) << c.name << ": no " << c.rule << " on line " << line;
    }
}

TEST(HostileNumbers, UnparsedNumbersLeaveTheFieldEmptyInTheModel) {
    std::string text = esi::test::sample_esi();
    // Every case whose text is still there (two cases replace the vendor Id).
    for (const auto& c : cases)
        if (text.find(c.from) != std::string::npos) text = esi::test::replace_once(text, c.from, c.to);
    const esi::ReadResult read = esi::read_esi(text, "numbers.xml");
    ASSERT_TRUE(read.document);
    const auto& info = read.document->infos.at(0);
    EXPECT_FALSE(info.vendor->id) << "a 65-bit vendor id must not wrap to a value";
    const auto& device = info.devices.at(0);
    EXPECT_FALSE(device.type.product_code);
    EXPECT_FALSE(device.type.revision_no);
    EXPECT_FALSE(device.sms.at(0).default_size) << "-1 must not become 0xFFFFFFFF";
}

TEST(HostileNumbers, EsiLintExitsOneOnEveryCase) {
    esi::test::TempDir dir;
    for (std::size_t i = 0; i < std::size(cases); ++i) {
        const auto path = dir / ("case" + std::to_string(i) + ".xml");
        esi::test::write_text(path, esi::test::replace_once(esi::test::sample_esi(), cases[i].from, cases[i].to));
    }
    const auto lint = esi::test::run_child({esi::test::tool("esi-lint").string(), "--format", "json", dir.path().string()});
    EXPECT_EQ(lint.exit_code, 1) << lint.err;
    for (const auto& c : cases) EXPECT_NE(lint.out.find(c.rule), std::string::npos) << c.name;
}

TEST(HostileNumbers, BitLenBeyondEightBitsIsNotWrittenToAnImage) {
    esi::test::TempDir dir;
    esi::test::write_text(dir / "device.xml", esi::test::replace_once(esi::test::sample_esi(), "<BitLen>8</BitLen>", "<BitLen>65536</BitLen>"));
    esi::test::write_text(dir / "out.bin", "previous image");
    const auto build = esi::test::run_child(
        {esi::test::tool("esi-sii").string(), "build", (dir / "device.xml").string(), "-o", (dir / "out.bin").string()});
    EXPECT_EQ(build.exit_code, 2);
    EXPECT_NE(build.err.find("[sii-value-range]"), std::string::npos) << build.err;
    EXPECT_EQ(esi::test::read_text(dir / "out.bin"), "previous image");
}
