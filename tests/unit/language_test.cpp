// The one table of languages (esi/model/language.hpp) the YAML source, the import and the model
// share: codes and LcIds are unique, so code -> LcId -> code is the identity.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "esi/model/language.hpp"

TEST(Language, CodesAndLcIdsAreUniqueAndMapBothWays) {
    std::set<std::string> codes;
    std::set<std::uint32_t> lcids;
    for (const esi::Language& language : esi::languages) {
        EXPECT_TRUE(codes.insert(std::string(language.code)).second) << language.code;
        EXPECT_TRUE(lcids.insert(language.lcid).second) << language.lcid;
        EXPECT_EQ(esi::lcid_of_language(language.code), language.lcid);
        EXPECT_EQ(esi::language_of_lcid(language.lcid), language.code);
    }
}

TEST(Language, SchemaDefaultIsEnglish) {
    EXPECT_EQ(esi::default_lcid, 1033u);
    EXPECT_EQ(esi::language_of_lcid(esi::default_lcid), "en");
    EXPECT_EQ(esi::lcid_of_language("de"), 1031u);
    EXPECT_EQ(esi::lcid_of_language("de-CH"), 2055u);
    EXPECT_EQ(esi::lcid_of_language("xx"), std::nullopt);
    EXPECT_EQ(esi::language_of_lcid(9999), std::nullopt);
}
