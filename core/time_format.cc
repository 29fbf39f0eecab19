#include "core/time_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace arbc {

namespace {

// Decimals of `per_second` units that show nanoseconds: the finest a trace records that matters.
int most_decimals(double per_second) {
  return static_cast<int>(std::lround(9 - std::log10(per_second)));
}

}  // namespace

TimeFormat::TimeFormat(double end, double resolution) {
  if (end >= 1) {
    unit_ = "s";
    per_second_ = 1;
  } else if (end >= 1e-3) {
    unit_ = "ms";
    per_second_ = 1e3;
  } else {
    unit_ = "\u00b5s";
    per_second_ = 1e6;
  }
  // Enough decimals for the resolution; at least milliseconds (3 decimals in seconds).
  double step = resolution > 0 ? resolution * per_second_ : 1;
  int needed = static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  int least = static_cast<int>(std::lround(3 - std::log10(per_second_)));
  decimals_ = std::clamp(std::max(needed, least), 0, most_decimals(per_second_));
}

TimeFormat TimeFormat::for_run(double length) {
  return length > 0 ? TimeFormat(length, length / 1000) : TimeFormat(1, 0);
}

std::string TimeFormat::number(double seconds, int decimals) const {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, seconds * per_second_);
  return buffer;
}

std::string TimeFormat::number(double seconds) const { return number(seconds, decimals_); }

std::string TimeFormat::text(double seconds) const { return number(seconds) + " " + unit_; }

std::string TimeFormat::span(double from, double to) const {
  int d = decimals_;
  while (d < most_decimals(per_second_) && from != to && number(from, d) == number(to, d)) ++d;
  return number(from, d) + "\u2013" + number(to, d) + " " + unit_;
}

}  // namespace arbc
