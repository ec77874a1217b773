// A name that starts with a bidi override (U+202E) cannot reorder its neighbours in esi-doc's
// index: every text from the ESI sits in its own bidi isolate (issue 27, item 3).

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace {

TEST(IndexBidi, NamesFromTheEsiAreIsolated) {
    esi::test::TempDir dir;
    const std::string rlo = "\u202E";
    esi::test::write_text(dir / "dev.xml",
                          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATInfo><Vendor><Id>#x00000ABC</Id><Name>Test</Name></Vendor>"
                          "<Descriptions><Groups><Group><Type>G</Type><Name>" + rlo + "Group</Name></Group></Groups><Devices>\n"
                          "<Device Physics=\"YY\"><Type ProductCode=\"#x1\" RevisionNo=\"#x1\">" + rlo + "Type</Type><Name>" + rlo +
                          "Evil name</Name><GroupType>G</GroupType></Device>\n</Devices></Descriptions></EtherCATInfo>\n");
    const auto r = esi::test::run({esi::test::tool("esi-doc").string(), (dir / "dev.xml").string(), "-o", (dir / "out").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string index = esi::test::read_text(dir / "out" / "index.html");
    for (const std::string text : {"Evil name", "Type", "Group"}) ASSERT_NE(index.find(rlo + text), std::string::npos) << text << "\n" << index;
    // Every override sits inside an isolate: the nearest <bdi> before it is not closed before it,
    // or, in the <title> (text only, no elements), the nearest first-strong isolate U+2068 is not
    // ended by U+2069 before it.
    const auto inside = [&](std::size_t at, const std::string& open_mark, const std::string& close_mark) {
        const std::size_t open = index.rfind(open_mark, at), close = index.rfind(close_mark, at);
        return open != std::string::npos && (close == std::string::npos || close < open);
    };
    std::size_t found = 0;
    for (std::size_t at = index.find(rlo); at != std::string::npos; at = index.find(rlo, at + 1), ++found)
        EXPECT_TRUE(inside(at, "<bdi>", "</bdi>") || inside(at, "&#x2068;", "&#x2069;")) << index.substr(at > 80 ? at - 80 : 0, 160);
    EXPECT_GE(found, 3u);
}

}  // namespace
