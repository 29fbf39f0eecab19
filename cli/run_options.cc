#include "cli/run_options.h"

#include <charconv>

#include "cli/duration_option.h"

namespace arbc::cli {

bool parse_run_duration(const std::string& text, double* seconds, std::string* err) {
  if (!parse_duration(text, BareNumber::Refused, false, seconds, err)) {
    *err = "--duration " + *err;
    return false;
  }
  if (*seconds > kMaxRunSeconds) {
    *err = "--duration '" + text +
           "' is longer than a run can be: at most 720h (30 days), beyond which the run's "
           "clock, seconds in a double, no longer resolves the 1 ns its deadlines are compared "
           "to (docs/design.md#events-and-lifetimes)";
    return false;
  }
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
