#include "examples/table_clean/arm.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "examples/table_clean/world.h"

namespace arbc::table_clean {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

class ArmTest : public ::testing::Test {
 protected:
  World world{1};
  int near_id = world.add_object(table_point(0.30, 0.2));
  int far_id = world.add_object(table_point(0.60, -0.2));
};

TEST_F(ArmTest, TakeGraspsAfterItsDurationAndReportsEachState) {
  Arm& arm = world.arm();
  EXPECT_THAT(arm.status(), ElementsAre("e_arm_idle"));
  arm.take(world.object(near_id).pos + Vec3(0.004, -0.003, 0.002), 0.0);
  EXPECT_THAT(arm.status(), IsEmpty());
  ASSERT_TRUE(arm.next_deadline());
  EXPECT_DOUBLE_EQ(*arm.next_deadline(), Arm::kTakeDuration);
  arm.update(Arm::kTakeDuration - 0.01);
  EXPECT_TRUE(arm.busy());
  arm.update(Arm::kTakeDuration);
  EXPECT_THAT(arm.status(), ElementsAre("e_taken", "e_arm_idle"));
  EXPECT_EQ(world.object(near_id).place, Place::Hand);
  EXPECT_EQ(arm.held(), near_id);
  EXPECT_EQ(world.conflicts().total(), 0);
}

TEST_F(ArmTest, PutIntoTheBucketEmptiesTheHand) {
  Arm& arm = world.arm();
  arm.take(world.object(near_id).pos, 0.0);
  arm.update(2.0);
  arm.put(World::bucket_position(), 2.0);
  EXPECT_THAT(arm.status(), ElementsAre("e_taken"));
  arm.update(2.0 + Arm::kPutDuration);
  EXPECT_THAT(arm.status(), ElementsAre("e_arm_idle"));
  EXPECT_EQ(world.object(near_id).place, Place::Bucket);
  EXPECT_EQ(world.objects_in_bucket(), 1);
  EXPECT_EQ(world.conflicts().total(), 0);
}

TEST_F(ArmTest, TakeWhileHoldingIsAConflictAndIsRefused) {
  Arm& arm = world.arm();
  arm.take(world.object(near_id).pos, 0.0);
  arm.update(2.0);
  arm.take(world.object(far_id).pos, 2.0);
  EXPECT_EQ(world.conflicts().count(ConflictKind::TakeWhileHolding), 1);
  EXPECT_FALSE(arm.busy());  // refused: nothing started
  EXPECT_EQ(world.conflicts().first_time(), 2.0);
}

TEST_F(ArmTest, TakeWhileTakingIsAConflict) {
  Arm& arm = world.arm();
  arm.take(world.object(near_id).pos, 0.0);
  arm.take(world.object(near_id).pos, 0.5);
  EXPECT_EQ(world.conflicts().count(ConflictKind::TakeWhileArmBusy), 1);
  arm.update(Arm::kTakeDuration);
  EXPECT_EQ(arm.held(), near_id);  // the first take still completes
}

TEST_F(ArmTest, TakeWhileTheRakeIsOutIsAConflict) {
  world.rake().pull(world.object(far_id).pos, 0.0);
  world.arm().take(world.object(near_id).pos, 0.5);
  EXPECT_EQ(world.conflicts().count(ConflictKind::TakeWhileRakeOut), 1);
  EXPECT_FALSE(world.arm().busy());
}

TEST_F(ArmTest, PutWithEmptyHandAndPutWhileBusyAreConflicts) {
  Arm& arm = world.arm();
  arm.put(World::bucket_position(), 0.0);
  EXPECT_EQ(world.conflicts().count(ConflictKind::PutWithEmptyHand), 1);
  arm.take(world.object(near_id).pos, 0.0);
  arm.update(2.0);
  arm.put(World::bucket_position(), 2.0);
  arm.put(World::bucket_position(), 2.5);
  EXPECT_EQ(world.conflicts().count(ConflictKind::PutWhileArmBusy), 1);
  EXPECT_EQ(world.conflicts().total(), 2);
}

TEST_F(ArmTest, TakeOfAnObjectOutOfHandReachComesBackEmpty) {
  Arm& arm = world.arm();
  arm.take(world.object(far_id).pos, 0.0);
  arm.update(2.0);
  EXPECT_FALSE(arm.holding());
  EXPECT_EQ(arm.failed_takes(), 1);
  EXPECT_EQ(world.object(far_id).place, Place::Table);
  EXPECT_EQ(world.conflicts().total(), 0);
}

TEST_F(ArmTest, AnObjectMayHaveSlippedOnTheWayToTheBucket) {
  world.perturbations().slip_first_put = true;
  Arm& arm = world.arm();
  arm.take(world.object(near_id).pos, 0.0);
  arm.update(2.0);
  arm.put(World::bucket_position(), 2.0);
  arm.update(2.0 + Arm::kPutDuration / 2);
  EXPECT_THAT(arm.status(), IsEmpty());  // no longer holding, still moving
  const TableObject& obj = world.object(near_id);
  EXPECT_EQ(obj.place, Place::Table);
  EXPECT_NE(zone_of(distance_from_robot(obj.pos)), Zone::Beyond);
  EXPECT_TRUE(clear_of_boundaries(distance_from_robot(obj.pos)));
  arm.update(2.0 + Arm::kPutDuration);
  EXPECT_THAT(arm.status(), ElementsAre("e_arm_idle"));
  EXPECT_EQ(arm.slips(), 1);
  // Only the first put slips (the object is put back within hand reach for the retry).
  world.object(near_id).pos = table_point(0.30, 0.0);
  arm.take(obj.pos, 4.0);
  arm.update(6.0);
  arm.put(World::bucket_position(), 6.0);
  arm.update(8.0);
  EXPECT_EQ(obj.place, Place::Bucket);
  EXPECT_EQ(arm.slips(), 1);
}

}  // namespace
}  // namespace arbc::table_clean
