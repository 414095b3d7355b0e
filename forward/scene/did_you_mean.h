// "Did you mean" suggestions for misspelt keys and enum values.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vs {

// Case-insensitive Levenshtein distance.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word` if it is close enough to be a plausible typo, else "".
std::string closest_match(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace vs
