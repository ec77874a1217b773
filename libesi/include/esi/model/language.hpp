#pragma once
// The languages of localized ESI texts: Name@LcId holds a Windows language id (ETG.2000; 1033,
// English, is the schema default). The YAML source writes them as codes (en, de …), esi-doc
// picks the page language with one, import writes them back: all use this one table.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "esi/model/common.hpp"

namespace esi {

struct Language {
    std::string_view code;  // "en", "de", "zh-TW" (BCP 47, as HTML's lang attribute takes it)
    std::uint32_t lcid = 0;
};

inline constexpr std::uint32_t english_lcid = 1033;

// The languages with a code, English first.
[[nodiscard]] std::span<const Language> languages();
[[nodiscard]] std::optional<std::uint32_t> lcid_of_language(std::string_view code);
// The code of a known LcId; nullopt for others.
[[nodiscard]] std::optional<std::string_view> language_code(std::uint32_t lcid);

// The text in the language `lcid`, else what primary_text() gives (English, the text without
// LcId, the first).
[[nodiscard]] const std::string& localized_text(const Names& names, std::uint32_t lcid);

}  // namespace esi
