// "Did you mean" suggestions by edit distance.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arbc::frontend {

// Levenshtein distance (insertions, deletions, substitutions), case-sensitive.
size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` if it is close enough to be a plausible typo: at most one
// edit for names up to four characters, two up to eight, three beyond. Ties go to the first.
std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string>& candidates);

}  // namespace arbc::frontend
