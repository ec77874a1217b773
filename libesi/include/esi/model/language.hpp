#pragma once
// Languages of localized texts (Name, Comment, URL …): the Windows language ids (LCIDs) ESI files
// write in @LcId (ETG.2000 NameType), and the codes the YAML device source writes them as.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "esi/model/common.hpp"

namespace esi {

// English (United States): the LcId of a text that gives none (EtherCATBase.xsd, NameType
// LcId default="1033").
inline constexpr std::uint32_t default_lcid = 1033;

struct Language {
    std::string_view code;  // "en", "de", "en-GB" …
    std::uint32_t lcid;
};

// The languages ESI files use; every code and every LcId appears once.
inline constexpr Language languages[] = {
    {"en", 1033},    {"de", 1031},    {"fr", 1036},    {"it", 1040},    {"es", 1034},    {"ja", 1041},
    {"zh", 2052},    {"ko", 1042},    {"ru", 1049},    {"pl", 1045},    {"nl", 1043},    {"sv", 1053},
    {"da", 1030},    {"fi", 1035},    {"pt", 2070},    {"cs", 1029},    {"tr", 1055},    {"hu", 1038},
    {"nb", 1044},    {"en-GB", 2057}, {"de-AT", 3079}, {"de-CH", 2055}, {"zh-TW", 1028}, {"pt-BR", 1046},
};

[[nodiscard]] constexpr std::optional<std::uint32_t> lcid_of_language(std::string_view code) {
    for (const Language& language : languages)
        if (language.code == code) return language.lcid;
    return std::nullopt;
}

[[nodiscard]] constexpr std::optional<std::string_view> language_of_lcid(std::uint32_t lcid) {
    for (const Language& language : languages)
        if (language.lcid == lcid) return language.code;
    return std::nullopt;
}

// The text in the language `lcid`, else what primary_text() gives (English, the text without
// LcId, the first): how esi-doc picks a page's texts.
[[nodiscard]] const std::string& localized_text(const Names& names, std::uint32_t lcid);

}  // namespace esi
