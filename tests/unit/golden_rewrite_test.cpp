// Golden files are rewritten only on ESI_UPDATE_GOLDEN=1; any other value (0, empty, yes) leaves
// them alone, so the comparison that follows still checks.

#include <gtest/gtest.h>

#include <cstdlib>

#include "support/test_support.hpp"

namespace esi::test {
namespace {

TEST(GoldenRewrite, OnlyTheValueOneRewritesTheFile) {
    TempDir dir;
    const auto golden = dir / "golden.txt";
    write_text(golden, "kept");
    for (const char* value : {"0", "", "yes", "true"}) {
        ::setenv("ESI_UPDATE_GOLDEN", value, 1);
        EXPECT_FALSE(rewrite_golden(golden, "new")) << "'" << value << "'";
        EXPECT_EQ(read_text(golden), "kept") << "'" << value << "'";
    }
    ::unsetenv("ESI_UPDATE_GOLDEN");
    EXPECT_FALSE(rewrite_golden(golden, "new"));
    ::setenv("ESI_UPDATE_GOLDEN", "1", 1);
    EXPECT_TRUE(rewrite_golden(golden, "new"));
    EXPECT_EQ(read_text(golden), "new");
    ::unsetenv("ESI_UPDATE_GOLDEN");
}

}  // namespace
}  // namespace esi::test
