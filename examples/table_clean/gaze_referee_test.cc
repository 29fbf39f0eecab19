#include "examples/table_clean/gaze_referee.h"

#include <gtest/gtest.h>

namespace arbc::table_clean {
namespace {

TEST(GazeReferee, ASearchTargetWithinTheHoldAfterAFaceTargetIsAConflict) {
  ConflictLog log;
  GazeReferee referee(log);
  const Vec3 face(1.0, 0.5, 0.4), look(1.5, -0.3, 0.2);
  referee.published(GazeSource::Face, face, 10.0);
  EXPECT_EQ(referee.delivered(face, 10.0), GazeSource::Face);
  referee.published(GazeSource::Search, look, 10.5);
  EXPECT_EQ(referee.delivered(look, 10.5), GazeSource::Search);
  EXPECT_EQ(log.count(ConflictKind::SearchDuringHold), 1);
}

TEST(GazeReferee, ASearchTargetAfterTheHoldIsFine) {
  ConflictLog log;
  GazeReferee referee(log);
  const Vec3 face(1.0, 0.5, 0.4), look(1.5, -0.3, 0.2);
  referee.published(GazeSource::Face, face, 10.0);
  referee.delivered(face, 10.0);
  referee.published(GazeSource::Search, look, 11.0);
  referee.delivered(look, 10.0 + GazeReferee::kHold);
  EXPECT_EQ(log.total(), 0);
  ASSERT_EQ(referee.search_resume_gaps().size(), 1u);
  EXPECT_DOUBLE_EQ(referee.search_resume_gaps()[0], 1.0);
}

TEST(GazeReferee, SearchWithoutAnyFaceTargetIsFine) {
  ConflictLog log;
  GazeReferee referee(log);
  referee.published(GazeSource::Search, Vec3(1, 2, 3), 0.0);
  referee.delivered(Vec3(1, 2, 3), 0.0);
  EXPECT_EQ(log.total(), 0);
  EXPECT_EQ(referee.search_targets(), 1);
  EXPECT_TRUE(referee.search_resume_gaps().empty());
}

TEST(GazeReferee, ATargetNobodyPublishedIsUnknown) {
  ConflictLog log;
  GazeReferee referee(log);
  referee.published(GazeSource::Face, Vec3(1, 2, 3), 0.0);
  EXPECT_EQ(referee.delivered(Vec3(1, 2, 3.1), 0.0), GazeSource::Unknown);
  EXPECT_EQ(referee.unknown_targets(), 1);
}

}  // namespace
}  // namespace arbc::table_clean
