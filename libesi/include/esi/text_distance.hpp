#pragma once
// "Did you mean …?" suggestions for misspelt keys, rule ids and element names.

#include <span>
#include <string>
#include <string_view>

namespace esi {

[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

// The closest candidate within a distance that scales with the word's length; empty if none.
[[nodiscard]] std::string closest_match(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace esi
