#include "examples/table_clean/geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace arbc::table_clean {
namespace {

TEST(Geometry, ZonesFollowThePaperBoundaries) {
  EXPECT_EQ(zone_of(0.10), Zone::Hand);
  EXPECT_EQ(zone_of(0.40), Zone::Hand);  // "within hand reach" includes the boundary
  EXPECT_EQ(zone_of(0.41), Zone::Tool);
  EXPECT_EQ(zone_of(0.75), Zone::Tool);
  EXPECT_EQ(zone_of(0.76), Zone::Beyond);
}

TEST(Geometry, PlacementRangesKeepTheMarginFromEveryBoundary) {
  for (Zone zone : {Zone::Hand, Zone::Tool, Zone::Beyond}) {
    const DistanceRange r = placement_range(zone);
    ASSERT_LT(r.min, r.max) << zone_name(zone);
    EXPECT_EQ(zone_of(r.min), zone);
    EXPECT_EQ(zone_of(r.max), zone);
    EXPECT_TRUE(clear_of_boundaries(r.min)) << zone_name(zone);
    EXPECT_TRUE(clear_of_boundaries(r.max)) << zone_name(zone);
  }
}

TEST(Geometry, DetectorNoiseCannotCrossTheMargin) {
  // The largest error a detection can have is the noise bound on all three axes at once.
  EXPECT_LT(kDetectorNoise * std::sqrt(3.0), kZoneMargin);
  // ... and it stays well inside the grasp tolerance, itself less than half the spacing.
  EXPECT_LT(kDetectorNoise * std::sqrt(3.0), kGraspTolerance);
  EXPECT_LT(2 * kGraspTolerance, kObjectSpacing + 1e-12);
}

TEST(Geometry, TablePointsLieOnTheTableAtTheGivenDistance) {
  const Vec3 p = table_point(0.5, 0.3);
  EXPECT_NEAR(distance_from_robot(p), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(p.z(), 0.0);
  EXPECT_NEAR(std::atan2(p.y(), p.x()), 0.3, 1e-12);
}

TEST(Geometry, AngleBetweenDirections) {
  EXPECT_NEAR(angle_between(Vec3(1, 0, 0), Vec3(0, 2, 0)), M_PI / 2, 1e-12);
  EXPECT_NEAR(angle_between(Vec3(1, 0, 0), Vec3(3, 0, 0)), 0.0, 1e-7);
}

}  // namespace
}  // namespace arbc::table_clean
