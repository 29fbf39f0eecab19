#include "core/time_text.h"

#include <cstdio>
#include <cstring>

namespace arbc {

std::string time_text(double t) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f", t);
  std::size_t length = std::strlen(buffer);
  // Trim in the buffer and build the string once: GCC 12 reports a false
  // -Wrestrict on assigning a literal to a string built from a buffer.
  if (std::memchr(buffer, '.', length) != nullptr) {  // not inf or nan
    while (buffer[length - 1] == '0') --length;
    if (buffer[length - 1] == '.') --length;
  }
  if (length == 2 && buffer[0] == '-' && buffer[1] == '0') return "0";
  return std::string(buffer, length);
}

}  // namespace arbc
