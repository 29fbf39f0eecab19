#include "examples/table_clean/rake.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "examples/table_clean/world.h"

namespace arbc::table_clean {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

class RakeTest : public ::testing::Test {
 protected:
  World world{2};
  int near_id = world.add_object(table_point(0.30, 0.3));
  int far_id = world.add_object(table_point(0.60, -0.2));
  Vec3 far_pos = world.object(far_id).pos;
};

constexpr double kRun =
    Rake::kFetchDuration + Rake::kReachDuration + Rake::kPullDuration + Rake::kReturnDuration;

TEST_F(RakeTest, APullFetchesReachesPullsReturnsThenIsIdle) {
  Rake& rake = world.rake();
  EXPECT_THAT(rake.status(), ElementsAre("e_pull_idle"));
  rake.pull(far_pos + Vec3(0.003, 0.003, -0.003), 0.0);
  EXPECT_EQ(rake.state(), RakeState::Fetching);
  EXPECT_THAT(rake.status(), IsEmpty());
  rake.update(1.0);
  EXPECT_EQ(rake.state(), RakeState::Reaching);
  rake.update(2.0);
  EXPECT_EQ(rake.state(), RakeState::Pulling);
  EXPECT_EQ(zone_of(distance_from_robot(world.object(far_id).pos)), Zone::Tool);
  rake.update(3.0);
  EXPECT_EQ(rake.state(), RakeState::Returning);
  const double dist = distance_from_robot(world.object(far_id).pos);
  EXPECT_EQ(zone_of(dist), Zone::Hand);
  EXPECT_TRUE(clear_of_boundaries(dist));
  EXPECT_GE((world.object(far_id).pos - world.object(near_id).pos).norm(), kObjectSpacing);
  EXPECT_THAT(rake.status(), IsEmpty());  // still out while it returns
  rake.update(kRun);
  EXPECT_EQ(rake.state(), RakeState::Idle);
  EXPECT_THAT(rake.status(), ElementsAre("e_pull_idle"));
  EXPECT_EQ(rake.objects_pulled(), 1);
  EXPECT_EQ(world.conflicts().total(), 0);
}

TEST_F(RakeTest, RedundantPullsWhileRakingAreIgnoredNotConflicts) {
  Rake& rake = world.rake();
  rake.pull(far_pos, 0.0);
  rake.pull(far_pos, 0.5);
  rake.pull(far_pos, 2.5);
  EXPECT_EQ(rake.redundant_pulls(), 2);
  EXPECT_EQ(world.conflicts().total(), 0);
  rake.update(kRun);
  EXPECT_EQ(rake.state(), RakeState::Idle);  // the run was not restarted
}

TEST_F(RakeTest, CancelSendsTheRakeBackThenReportsIdle) {
  Rake& rake = world.rake();
  rake.pull(far_pos, 0.0);
  rake.cancel(1.5);  // while reaching
  EXPECT_EQ(rake.state(), RakeState::Returning);
  EXPECT_EQ(rake.cancels_honoured(), 1);
  rake.update(1.5 + Rake::kReturnDuration - 0.01);
  EXPECT_TRUE(rake.out());
  rake.update(1.5 + Rake::kReturnDuration);
  EXPECT_EQ(rake.state(), RakeState::Idle);
  EXPECT_EQ(rake.objects_pulled(), 0);
  EXPECT_EQ(world.object(far_id).pos, far_pos);  // untouched
}

TEST_F(RakeTest, CancelWhileIdleOrReturningIsIgnoredNotAConflict) {
  Rake& rake = world.rake();
  rake.cancel(0.0);
  rake.pull(far_pos, 0.0);
  rake.update(3.5);  // returning
  ASSERT_EQ(rake.state(), RakeState::Returning);
  rake.cancel(3.5);
  EXPECT_EQ(rake.cancels_ignored(), 2);
  EXPECT_EQ(rake.cancels_honoured(), 0);
  rake.update(kRun);
  EXPECT_EQ(rake.state(), RakeState::Idle);
  EXPECT_EQ(world.conflicts().total(), 0);
}

TEST_F(RakeTest, PullWhileTheArmIsBusyOrHoldingIsAConflict) {
  world.arm().take(world.object(near_id).pos, 0.0);
  world.rake().pull(far_pos, 0.5);
  EXPECT_EQ(world.conflicts().count(ConflictKind::PullWhileArmBusy), 1);
  EXPECT_FALSE(world.rake().out());
  world.arm().update(2.0);
  ASSERT_TRUE(world.arm().holding());
  world.rake().pull(far_pos, 2.0);
  EXPECT_EQ(world.conflicts().count(ConflictKind::PullWhileHolding), 1);
  EXPECT_FALSE(world.rake().out());
}

TEST_F(RakeTest, TheRakePullsNothingWhenThePersonMovedTheTarget) {
  world.perturbations().person_moves_first_rake_target = true;
  Rake& rake = world.rake();
  rake.pull(far_pos, 0.0);
  rake.update(1.0);  // reaching: the person's move is on the agenda
  world.advance_to(1.5);
  EXPECT_EQ(zone_of(distance_from_robot(world.object(far_id).pos)), Zone::Hand);
  EXPECT_EQ(world.person().objects_moved(), 1);
  rake.update(kRun);
  EXPECT_EQ(rake.objects_pulled(), 0);
}

}  // namespace
}  // namespace arbc::table_clean
