#include "cli/duration_option.h"

#include <cstdio>

namespace arbc::cli {

CLI::Validator seconds_option(bool zero_allowed) {
  return CLI::Validator(
      [zero_allowed](std::string& text) -> std::string {
        double seconds = 0;
        std::string why;
        if (!parse_duration(text, BareNumber::Seconds, zero_allowed, &seconds, &why)) return why;
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.17g", seconds);
        text = buffer;
        return "";
      },
      "");
}

}  // namespace arbc::cli
