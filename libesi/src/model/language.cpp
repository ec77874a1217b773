#include "esi/model/language.hpp"

#include <array>

namespace esi {

namespace {

constexpr std::array known_languages{
    Language{"en", 1033}, Language{"de", 1031}, Language{"fr", 1036}, Language{"it", 1040}, Language{"es", 1034},
    Language{"ja", 1041}, Language{"zh", 2052}, Language{"ko", 1042}, Language{"ru", 1049}, Language{"pl", 1045},
    Language{"nl", 1043}, Language{"sv", 1053}, Language{"da", 1030}, Language{"fi", 1035}, Language{"pt", 2070},
    Language{"cs", 1029}, Language{"tr", 1055}, Language{"hu", 1038}, Language{"nb", 1044}, Language{"en-GB", 2057},
    Language{"de-AT", 3079}, Language{"de-CH", 2055}, Language{"zh-TW", 1028}, Language{"pt-BR", 1046},
};

}  // namespace

std::span<const Language> languages() { return known_languages; }

std::optional<std::uint32_t> lcid_of_language(std::string_view code) {
    for (const auto& l : known_languages)
        if (l.code == code) return l.lcid;
    return std::nullopt;
}

std::optional<std::string_view> language_code(std::uint32_t lcid) {
    for (const auto& l : known_languages)
        if (l.lcid == lcid) return l.code;
    return std::nullopt;
}

const std::string& localized_text(const Names& names, std::uint32_t lcid) {
    if (const LocalizedText* wanted = find_lcid(names, lcid)) return wanted->text;
    return primary_text(names);
}

}  // namespace esi
