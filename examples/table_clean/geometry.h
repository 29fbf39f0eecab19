// The table's geometry: the robot sits at the origin, the table top is the plane z = 0 in front
// of it (+x), and an object's distance is its distance from the origin. The paper's three zones
// (examples/table_clean/README.md#the-world-worldh) follow from that distance alone.
#pragma once

#include <Eigen/Core>
#include <string_view>

namespace arbc::table_clean {

using Vec3 = Eigen::Vector3d;

inline constexpr double kHandReach = 0.40;  // metres; the spec's HAND_REACHABLE
inline constexpr double kToolReach = 0.75;  // metres; the spec's TOOL_REACHABLE
// Objects are placed at least this far from a zone boundary, so that detector noise (smaller,
// see kDetectorNoise) can never put an object in the wrong zone.
inline constexpr double kZoneMargin = 0.02;
// Each coordinate of a detection is off by at most this much: |error| <= 0.005 * sqrt(3) < 1 cm.
inline constexpr double kDetectorNoise = 0.005;
// Objects on the table keep at least this distance between their centres, so that a commanded
// position (off by detector noise) names exactly one object.
inline constexpr double kObjectSpacing = 0.08;
// A `take` or `pull` finds the object nearest to its position within this radius.
inline constexpr double kGraspTolerance = 0.04;

enum class Zone { Hand, Tool, Beyond };

std::string_view zone_name(Zone zone);

// Distance from the robot: what the detectors report as `dist`.
double distance_from_robot(const Vec3& pos);

// The zone of a distance: within hand reach (<= kHandReach), within tool reach (<= kToolReach),
// or beyond.
Zone zone_of(double dist);

// True when `dist` lies at least kZoneMargin from both zone boundaries.
bool clear_of_boundaries(double dist);

// The range of distances where objects of a zone are placed: inside the zone, kZoneMargin from
// its boundaries, and on the table.
struct DistanceRange {
  double min = 0;
  double max = 0;
};
DistanceRange placement_range(Zone zone);

// A point on the table top at `dist` from the robot and `azimuth` radians from straight ahead
// (+y is positive azimuth).
Vec3 table_point(double dist, double azimuth);

// Angle in radians between two non-zero directions.
double angle_between(const Vec3& a, const Vec3& b);

}  // namespace arbc::table_clean
