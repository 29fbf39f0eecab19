// "Did you mean" suggestions by edit distance.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arbc {

// Edit distance (insertions, deletions, substitutions, and swaps of two adjacent characters,
// the commonest typo: `lne` for `len` is one edit), case-sensitive. Optimal string alignment:
// a swapped pair is not edited again.
size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` if it is close enough to be a plausible typo: at most one
// edit for names up to four characters, two up to eight, three beyond. Ties go to the first.
std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string>& candidates);

}  // namespace arbc
