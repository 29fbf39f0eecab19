#include "core/instant.h"

#include <cmath>
#include <string>

#include "core/decimal_text.h"

namespace arbc {

namespace {

constexpr int64_t kPerSecond = 1'000'000'000;

// 10^n for n <= 18.
int64_t power_of_ten(size_t n) {
  int64_t p = 1;
  for (size_t i = 0; i < n; ++i) p *= 10;
  return p;
}

bool all_digits(std::string_view s) {
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

}  // namespace

Nanos nanos_from_seconds(double seconds) {
  if (std::isnan(seconds)) return Nanos(0);
  double n = std::round(seconds * 1e9);
  // 2^63 is exactly representable; a double at or beyond it does not fit an int64_t.
  if (n >= 9223372036854775808.0) return kNever;
  if (n <= -9223372036854775808.0) return -kNever;
  return Nanos(static_cast<int64_t>(n));
}

std::string decimal_seconds(Nanos t) {
  int64_t n = t.count();
  // The magnitude as unsigned: -INT64_MIN does not fit an int64_t.
  uint64_t magnitude = n < 0 ? 0 - static_cast<uint64_t>(n) : static_cast<uint64_t>(n);
  std::string out = n < 0 ? "-" : "";
  out += std::to_string(magnitude / kPerSecond);
  uint64_t fraction = magnitude % kPerSecond;
  if (fraction == 0) return out;
  std::string digits = std::to_string(fraction);
  digits.insert(0, 9 - digits.size(), '0');
  while (digits.back() == '0') digits.pop_back();
  return out + "." + digits;
}

std::optional<Nanos> nanos_of_decimal(std::string_view digits, int64_t unit) {
  size_t point = digits.find('.');
  std::string_view whole = digits.substr(0, point);
  std::string_view fraction =
      point == std::string_view::npos ? std::string_view() : digits.substr(point + 1);
  if (whole.empty() || !all_digits(whole) || !all_digits(fraction) || unit <= 0)
    return std::nullopt;
  while (!fraction.empty() && fraction.back() == '0') fraction.remove_suffix(1);
  while (whole.size() > 1 && whole.front() == '0') whole.remove_prefix(1);
  // kLongestDuration is under 2^62 ns, so a whole part of more than 19 digits, or a fraction
  // that a unit of at most 18 digits cannot make whole, is out at once; the rest fits __int128.
  if (whole.size() > 19 || fraction.size() > 18) return std::nullopt;
  __int128 w = 0, f = 0;
  for (char c : whole) w = w * 10 + (c - '0');
  for (char c : fraction) f = f * 10 + (c - '0');
  __int128 scale = power_of_ten(fraction.size());
  __int128 fraction_nanos = f * unit;
  if (fraction_nanos % scale != 0) return std::nullopt;  // not a whole number of nanoseconds
  __int128 total = w * unit + fraction_nanos / scale;
  if (total > kLongestDuration.count()) return std::nullopt;
  return Nanos(static_cast<int64_t>(total));
}

std::optional<Nanos> whole_nanos(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return std::nullopt;
  return nanos_of_decimal(shortest_decimal(seconds), kPerSecond);
}

}  // namespace arbc
