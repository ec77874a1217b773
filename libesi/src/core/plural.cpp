#include "esi/plural.hpp"

namespace esi {

std::string counted(std::uint64_t n, std::string_view singular, std::string_view plural) {
    std::string out = std::to_string(n);
    out += ' ';
    if (n == 1) out += singular;
    else if (!plural.empty()) out += plural;
    else {
        out += singular;
        out += 's';
    }
    return out;
}

}  // namespace esi
