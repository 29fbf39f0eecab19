#include "core/duration_parse.h"

#include <charconv>
#include <cmath>

namespace arbc {

namespace {

// Seconds per unit; 0: not a unit.
double unit_seconds(const std::string& unit) {
  if (unit == "ms") return 1e-3;
  if (unit == "s") return 1;
  if (unit == "min") return 60;
  if (unit == "h") return 3600;
  return 0;
}

}  // namespace

bool parse_duration(const std::string& text, BareNumber bare, bool zero_allowed, double* seconds,
                    std::string* why) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  double value = 0;
  auto [stop, ec] = std::from_chars(begin, end, value);
  std::string unit(stop, end);
  std::string wanted = bare == BareNumber::Seconds
                           ? std::string("a number of seconds, or a number and its unit (") +
                                 kDurationUnits + "), such as 30, 500ms, 2min or 1h"
                           : std::string("a number and its unit (") + kDurationUnits +
                                 "), such as 60s, 500ms, 2min or 3h";
  const char* positive = zero_allowed ? "" : "positive ";
  std::string start =
      "'" + text + "' is not a " + positive +
      (bare == BareNumber::Seconds ? "number of seconds" : "duration with its unit");
  if (ec != std::errc()) {
    *why = start + ": write " + wanted;
    return false;
  }
  double scale = unit.empty() && bare == BareNumber::Seconds ? 1 : unit_seconds(unit);
  if (scale == 0) {
    *why = start + (unit.empty()
                        ? " (write " + text + "s for seconds)"
                        : ": '" + unit + "' is not a unit of time; the units are " +
                              std::string(kDurationUnits) + " (such as 60s, 500ms, 2min, 3h)");
    return false;
  }
  double total = value * scale;
  if (!std::isfinite(total)) {
    *why = start + ": write " + wanted;
    return false;
  }
  if (total < 0 || (total == 0 && !zero_allowed)) {
    *why = start + (zero_allowed ? " (it must be 0 or more)" : " (it must be above 0)");
    return false;
  }
  *seconds = total;
  return true;
}

}  // namespace arbc
