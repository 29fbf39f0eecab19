#include "examples/table_clean/geometry.h"

#include <algorithm>
#include <cmath>

namespace arbc::table_clean {

std::string_view zone_name(Zone zone) {
  switch (zone) {
    case Zone::Hand:
      return "hand";
    case Zone::Tool:
      return "tool";
    case Zone::Beyond:
      return "beyond";
  }
  return "?";
}

double distance_from_robot(const Vec3& pos) { return pos.norm(); }

Zone zone_of(double dist) {
  if (dist <= kHandReach) return Zone::Hand;
  if (dist <= kToolReach) return Zone::Tool;
  return Zone::Beyond;
}

bool clear_of_boundaries(double dist) {
  return std::abs(dist - kHandReach) >= kZoneMargin && std::abs(dist - kToolReach) >= kZoneMargin;
}

DistanceRange placement_range(Zone zone) {
  // The table starts 15 cm in front of the robot and ends at 1 m.
  switch (zone) {
    case Zone::Hand:
      return {0.18, kHandReach - kZoneMargin};
    case Zone::Tool:
      return {kHandReach + kZoneMargin, kToolReach - kZoneMargin};
    case Zone::Beyond:
      return {kToolReach + kZoneMargin, 0.95};
  }
  return {};
}

Vec3 table_point(double dist, double azimuth) {
  return Vec3(dist * std::cos(azimuth), dist * std::sin(azimuth), 0.0);
}

double angle_between(const Vec3& a, const Vec3& b) {
  const double c = a.normalized().dot(b.normalized());
  return std::acos(std::clamp(c, -1.0, 1.0));
}

}  // namespace arbc::table_clean
