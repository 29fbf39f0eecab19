#include "core/time_text.h"

#include <cstdio>

namespace arbc {

std::string time_text(double t) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f", t);
  std::string s = buffer;
  if (s.find('.') == std::string::npos) return s;  // inf, nan
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

}  // namespace arbc
