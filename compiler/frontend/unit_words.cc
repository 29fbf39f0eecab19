#include "compiler/frontend/unit_words.h"

#include <cctype>

namespace arbc::frontend {

std::optional<std::string> duration_unit(std::string_view word) {
  // The spellings are few and fixed; anything else (m, cm, deg) is not a time at all.
  for (std::string_view w : {"s", "sec", "secs", "second", "seconds"})
    if (word == w) return "s";
  for (std::string_view w : {"ms", "msec", "msecs", "millisecond", "milliseconds"})
    if (word == w) return "ms";
  for (std::string_view w : {"min", "mins", "minute", "minutes"})
    if (word == w) return "min";
  return std::nullopt;
}

std::pair<std::string, std::string> split_number_suffix(std::string_view text) {
  size_t i = 0;
  while (i < text.size() && !std::isalpha(static_cast<unsigned char>(text[i])) && text[i] != '_')
    ++i;
  return {std::string(text.substr(0, i)), std::string(text.substr(i))};
}

}  // namespace arbc::frontend
