#include "cli/run_options.h"

#include <charconv>
#include <cmath>

namespace arbc::cli {

bool parse_run_duration(const std::string& text, double* seconds, std::string* err) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  double value = 0;
  auto [unit, ec] = std::from_chars(begin, end, value);
  std::string suffix(unit, end);
  double scale = suffix == "s" ? 1 : suffix == "ms" ? 1e-3 : suffix == "min" ? 60 : 0;
  if (ec != std::errc() || scale == 0 || !std::isfinite(value) || !(value > 0)) {
    *err = "--duration '" + text + "' is not a positive duration with its unit, such as 60s, " +
           "500ms or 2min";
    if (ec == std::errc() && suffix.empty() && value > 0)
      *err += " (write " + text + "s for seconds)";
    return false;
  }
  *seconds = value * scale;
  return true;
}

bool parse_seed(const std::string& text, uint64_t* seed, std::string* err) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  uint64_t value = 0;
  auto [stop, ec] = std::from_chars(begin, end, value);
  if (text.empty() || ec != std::errc() || stop != end) {
    *err = "--seed '" + text + "' is not a whole number from 0 to 18446744073709551615";
    return false;
  }
  *seed = value;
  return true;
}

}  // namespace arbc::cli
