#include "core/decimal_text.h"

#include <cstdio>
#include <cstdlib>

namespace arbc {

std::string shortest_decimal(double v) {
  // Scientific form with the fewest significant digits that reads back as v.
  char text[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*e", digits - 1, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  // text is [-]D[.DDD]e(+|-)XX: split it into the sign, the digits and the exponent.
  std::string s = text;
  std::string sign = s[0] == '-' ? "-" : "";
  if (!sign.empty()) s.erase(0, 1);
  size_t e = s.find('e');
  int exponent = std::atoi(s.c_str() + e + 1);
  std::string digits;
  for (char c : s.substr(0, e))
    if (c != '.') digits += c;
  // The value is 0.DIGITS * 10^(exponent + 1): place the point, padding with zeros.
  int point = exponent + 1;  // digits before the decimal point
  std::string out;
  if (point <= 0) {
    out = "0." + std::string(static_cast<size_t>(-point), '0') + digits;
  } else if (static_cast<size_t>(point) >= digits.size()) {
    out = digits + std::string(static_cast<size_t>(point) - digits.size(), '0');
  } else {
    out = digits.substr(0, static_cast<size_t>(point)) + "." +
          digits.substr(static_cast<size_t>(point));
  }
  return digits == "0" ? "0" : sign + out;
}

}  // namespace arbc
