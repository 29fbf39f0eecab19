#include "core/duration_literal.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace arbc {

namespace {

// `value` with `decimals` places, trailing zeros (and a bare point) dropped.
std::string trimmed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::size_t length = std::strlen(buffer);
  if (std::memchr(buffer, '.', length) != nullptr) {
    while (buffer[length - 1] == '0') --length;
    if (buffer[length - 1] == '.') --length;
  }
  return std::string(buffer, length);
}

}  // namespace

std::string duration_literal(Nanos t) {
  if (t == Nanos(0)) return "0s";
  if (t >= std::chrono::seconds(1) || t <= -std::chrono::seconds(1))
    return decimal_seconds(t) + "s";
  // decimal_seconds of a thousand times t, read as milliseconds: exact, with the same trimming.
  return decimal_seconds(t * 1000) + "ms";
}

std::string duration_literal(double seconds) {
  if (!std::isfinite(seconds)) return trimmed(seconds, 0) + "s";
  // Rounded to the microsecond first, so that 0.9999999 reads 1s, not 1000ms, and the sums of
  // decimal periods a simulated clock makes (0.1 + 0.2) read as written.
  double micros = std::round(seconds * 1e6);
  if (micros == 0) return "0s";
  if (std::abs(micros) < 1e6) return trimmed(micros / 1e3, 3) + "ms";
  return trimmed(micros / 1e6, 6) + "s";
}

std::string age_literal(Nanos age) {
  return duration_literal(Nanos(std::chrono::duration_cast<std::chrono::milliseconds>(age)));
}

}  // namespace arbc
