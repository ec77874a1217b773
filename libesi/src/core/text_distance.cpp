#include "esi/text_distance.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace esi {

std::size_t edit_distance(std::string_view a, std::string_view b) {
    // Case-insensitive Levenshtein distance, two rows.
    std::vector<std::size_t> previous(b.size() + 1);
    std::vector<std::size_t> current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::string closest_match(std::string_view word, std::span<const std::string_view> candidates) {
    const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
    std::size_t best = limit + 1;
    std::string_view best_candidate;
    for (std::string_view candidate : candidates) {
        // The distance is at least the difference in length: candidates that cannot beat the best
        // are skipped, so a hostile multi-megabyte word costs no quadratic comparison.
        const std::size_t length_difference =
            word.size() > candidate.size() ? word.size() - candidate.size() : candidate.size() - word.size();
        if (length_difference >= best) continue;
        const std::size_t d = edit_distance(word, candidate);
        if (d < best) {
            best = d;
            best_candidate = candidate;
        }
    }
    return best <= limit ? std::string(best_candidate) : std::string();
}

}  // namespace esi
