// The one language table (esi/model/language.hpp): codes and LcIds both ways, and the fallback
// when a text is not given in the language asked for.

#include <gtest/gtest.h>

#include "esi/model/language.hpp"

namespace {

esi::Names names(std::initializer_list<std::pair<std::optional<std::uint32_t>, const char*>> texts) {
    esi::Names out;
    for (const auto& [lcid, text] : texts) out.push_back({text, lcid, {}});
    return out;
}

TEST(Language, CodesAndLcIdsRoundTrip) {
    EXPECT_EQ(esi::lcid_of_language("en"), 1033u);
    EXPECT_EQ(esi::lcid_of_language("de"), 1031u);
    EXPECT_EQ(esi::lcid_of_language("zh-TW"), 1028u);
    EXPECT_EQ(esi::lcid_of_language("xx"), std::nullopt);
    for (const auto& l : esi::languages()) EXPECT_EQ(esi::language_code(l.lcid), l.code);
    EXPECT_EQ(esi::language_code(9999), std::nullopt);
    EXPECT_EQ(esi::languages().front().code, "en");
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
