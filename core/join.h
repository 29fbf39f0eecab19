// Joining names into one line of text: the one join of the project.
#pragma once

#include <iterator>
#include <string>
#include <string_view>

namespace arbc {

// The items with `sep` between them, and `last_sep` instead before the last one when given:
//   join(v) == "a, b, c"      join(v, ", ", " or ") == "a, b or c"
// `items` is any range of strings (a vector, a set, a span); no items give "".
template <class Range>
std::string join(const Range& items, std::string_view sep = ", ", std::string_view last_sep = {}) {
  std::string out;
  const size_t n = std::size(items);
  size_t i = 0;
  for (const auto& item : items) {
    if (i > 0) out += (i + 1 == n && !last_sep.empty()) ? last_sep : sep;
    out += item;
    ++i;
  }
  return out;
}

}  // namespace arbc
