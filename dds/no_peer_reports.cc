#include "dds/no_peer_reports.h"

#include <cstdio>

namespace arbc::dds {

double no_peer_report_at(int k, double first) {
  // In units of the first report's time: 1, 3, 6, 12, 30, then every 30.
  static const double kSteps[] = {1, 3, 6, 12, 30};
  constexpr int kCount = sizeof kSteps / sizeof kSteps[0];
  if (k < 0) k = 0;
  if (k < kCount) return first * kSteps[k];
  return first * (kSteps[kCount - 1] + 30.0 * (k - kCount + 1));
}

std::string wall_span_text(double seconds) {
  char text[48];
  if (seconds < 60) {
    std::snprintf(text, sizeof text, "%g s", seconds);
  } else {
    std::snprintf(text, sizeof text, "%g min", seconds / 60);
  }
  return text;
}

}  // namespace arbc::dds
