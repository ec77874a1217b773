#include "esi/model/language.hpp"

namespace esi {

const std::string& localized_text(const Names& names, std::uint32_t lcid) {
    if (const LocalizedText* wanted = find_lcid(names, lcid)) return wanted->text;
    return primary_text(names);
}

}  // namespace esi
