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

namespace {

esi::Names names(std::initializer_list<std::pair<std::optional<std::uint32_t>, const char*>> texts) {
    esi::Names out;
    for (const auto& [lcid, text] : texts) out.push_back({text, lcid, {}});
    return out;
}

TEST(Language, LocalizedTextPicksTheLanguageElseEnglishElseUnmarkedElseFirst) {
    const esi::Names all = names({{1031, "Digitaler Eingang"}, {1033, "Digital input"}, {1036, "Entrée"}});
    EXPECT_EQ(esi::localized_text(all, 1031), "Digitaler Eingang");
    EXPECT_EQ(esi::localized_text(all, 1036), "Entrée");
    EXPECT_EQ(esi::localized_text(all, 1041), "Digital input");
    EXPECT_EQ(esi::localized_text(names({{1031, "Eingang"}, {std::nullopt, "Input"}}), 1041), "Input");
    EXPECT_EQ(esi::localized_text(names({{1031, "Eingang"}, {1036, "Entrée"}}), 1041), "Eingang");
    EXPECT_EQ(esi::localized_text({}, 1033), "");
}

}  // namespace
