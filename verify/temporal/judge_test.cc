// The runtime's word on a replayed counterexample (verify/temporal/judge.h): each shape judged
// on a port's records as the runtime writes them, including the boundaries (an entry absent at
// its expiry instant, a lapse that must not remove a later refresh).
#include "verify/temporal/judge.h"

#include <gtest/gtest.h>

#include "verify/temporal/replay_records_for_tests.h"

namespace arbc::verify::temporal {
namespace {

using namespace std::chrono_literals;

using P = model::TemporalProperty;

using namespace records;  // at, deliver, set, remove: records written in seconds

P absence() {
  P p{P::Kind::Absence, "HeadControl.gaze", "search", 0s, {}, "", "", false, {}};
  p.event = "act_track";
  return p;
}

P precedence() {
  P p{P::Kind::Precedence, "PickAndPlace.cmd", "put", 0s, {}, "", "", false, {}};
  p.other = "take";
  return p;
}

TEST(Judge, AbsenceIsViolatedByADeliveryWhileTheEventIsPresent) {
  std::string seen;
  EXPECT_TRUE(replay_violates(
      absence(), {deliver(0, "track"), set(0, "track", "act_track", 1), deliver(0.5, "search")},
      &seen));
  // At the expiry instant the event is absent (docs/design.md#events-and-lifetimes).
  EXPECT_FALSE(replay_violates(
      absence(), {deliver(0, "track"), set(0, "track", "act_track", 1), deliver(1, "search")},
      &seen));
  EXPECT_NE(seen.find("'search' delivered at 1s, each time without act_track"), std::string::npos)
      << seen;
  // The activity event is set after its own delivery: track's record sees the state before.
  P own = absence();
  own.rule = "track";
  EXPECT_FALSE(replay_violates(own, {deliver(0, "track"), set(0, "track", "act_track", 1)}, &seen));
}

TEST(Judge, AbsenceFollowsUnsetsAndLapsesPerOwner) {
  std::string seen;
  P p = absence();
  p.event = "e";
  // Unset by one owner leaves the other's entry.
  EXPECT_TRUE(replay_violates(p,
                              {set(0, "a", "e", -1), set(0, "b", "e", -1),
                               remove(0.1, "a", "e", -1), deliver(0.2, "search")},
                              &seen));
  EXPECT_FALSE(replay_violates(
      p, {set(0, "a", "e", -1), remove(0.1, "a", "e", -1), deliver(0.2, "search")}, &seen));
  // A lapse recorded after a refresh does not remove the refreshed entry.
  EXPECT_TRUE(replay_violates(p,
                              {set(0, "a", "e", 1), set(0.9, "a", "e", 1.9), remove(1, "a", "e", 1),
                               deliver(1.5, "search")},
                              &seen));
}

TEST(Judge, PrecedenceNeedsAFreshDeliveryOfTheOtherRuleBeforeEach) {
  std::string seen;
  EXPECT_TRUE(replay_violates(precedence(), {deliver(0, "put")}, &seen));
  EXPECT_TRUE(replay_violates(precedence(),
                              {deliver(0, "take"), deliver(1, "put"), deliver(2, "put")}, &seen));
  EXPECT_FALSE(replay_violates(
      precedence(), {deliver(0, "take"), deliver(0, "put"), deliver(1, "take"), deliver(2, "put")},
      &seen));
  EXPECT_NE(seen.find("take at 0s, put at 0s, take at 1s, put at 2s"), std::string::npos) << seen;
  // Other rules of the port do not count.
  EXPECT_TRUE(replay_violates(precedence(), {deliver(0, "pull"), deliver(1, "put")}, &seen));
}

TEST(Judge, SpacingLooksOnlyAtTheRulesDeliveries) {
  std::string seen;
  P p{P::Kind::Spacing, "PickAndPlace.cmd", "take", 1s, {}, "", "", false, {}};
  EXPECT_TRUE(replay_violates(p, {deliver(0, "take"), deliver(0.999, "take")}, &seen));
  EXPECT_FALSE(
      replay_violates(p, {deliver(0, "take"), deliver(0.5, "put"), deliver(1, "take")}, &seen));
  EXPECT_NE(seen.find("'take' delivered at 0s, 1s"), std::string::npos) << seen;
}

TEST(Judge, AReplayMustKeepTheAssumptionAtEachDelivery) {
  model::Assumption a{"e_taken", "PickAndPlace.cmd", "take", "put", {}, std::nullopt};
  std::string broken;
  // Reported after the take, withdrawn before the next put: kept.
  EXPECT_TRUE(
      replay_respects(a,
                      {deliver(0, "take"), set(0.1, "h", "e_taken", -1), deliver(0.2, "put"),
                       remove(0.3, "h", "e_taken", -1), deliver(0.4, "put")},
                      &broken));
  // Reported before any take.
  EXPECT_FALSE(replay_respects(a, {set(0, "h", "e_taken", -1), deliver(0.1, "put")}, &broken));
  EXPECT_NE(broken.find("e_taken was present when 'put' delivered at 100ms"), std::string::npos)
      << broken;
  // Still reported at a delivery after the put.
  EXPECT_FALSE(replay_respects(
      a,
      {deliver(0, "take"), set(0.1, "h", "e_taken", -1), deliver(0.2, "put"), deliver(0.3, "put")},
      &broken));
  // A lapsed entry is no longer present.
  EXPECT_TRUE(replay_respects(
      a,
      {deliver(0, "take"), set(0.1, "h", "e_taken", 0.5), deliver(0.2, "put"), deliver(0.5, "put")},
      &broken));
}

TEST(Judge, ASpacingAfterAnotherRuleMeasuresFromItsLastDelivery) {
  P p{P::Kind::Spacing, "HeadControl.gaze", "search", 1s, {}, "", "track", false, {}};
  std::string seen;
  EXPECT_TRUE(replay_violates(p, {deliver(0, "track"), deliver(0.6, "search")}, &seen));
  // At the window's end, and before any track, search may deliver; two searches are no matter.
  EXPECT_FALSE(replay_violates(
      p,
      {deliver(0, "search"), deliver(0.1, "search"), deliver(0.2, "track"), deliver(1.2, "search")},
      &seen));
  EXPECT_NE(seen.find("'search' delivered at 0s, 100ms, 1.2s, 'track' at 200ms"), std::string::npos)
      << seen;
  // A later track restarts the window.
  EXPECT_TRUE(replay_violates(
      p, {deliver(0, "track"), deliver(0.9, "track"), deliver(1.5, "search")}, &seen));
}

TEST(Judge, AReplayMustKeepTheTimedAssumptionForItsWindow) {
  model::Assumption a{"e_arm_idle", "PickAndPlace.cmd", "take", "", {}, 1s};
  std::string broken;
  // Withdrawn at the take, reported again a second later: kept.
  EXPECT_TRUE(replay_respects(
      a,
      {set(0, "h", "e_arm_idle", -1), deliver(0, "take"), remove(0, "h", "e_arm_idle", -1),
       deliver(0.5, "put"), set(1, "h", "e_arm_idle", -1), deliver(1, "take")},
      &broken));
  // Still present half a second after the take.
  EXPECT_FALSE(replay_respects(
      a, {set(0, "h", "e_arm_idle", -1), deliver(0, "take"), deliver(0.5, "take")}, &broken));
  EXPECT_NE(broken.find("e_arm_idle was present when 'take' delivered at 500ms, less than 1s "
                        "after take delivered at 0s"),
            std::string::npos)
      << broken;
  // Present before any take: the timed form says nothing there.
  EXPECT_TRUE(replay_respects(a, {set(0, "h", "e_arm_idle", -1), deliver(0.5, "put")}, &broken));
  // Its window ends exactly a second after the take: present at 1 s is kept, a nanosecond
  // before is not.
  EXPECT_TRUE(replay_respects(
      a, {set(0, "h", "e_arm_idle", -1), deliver(0, "take"), deliver(1, "put")}, &broken));
  EXPECT_FALSE(replay_respects(
      a, {set(0, "h", "e_arm_idle", -1), deliver(0, "take"), deliver(0.999999999, "put")},
      &broken));
}

// The runtime's instants are whole nanoseconds and so is every judgement of them
// (core/instant.h): a spacing, an absence and a spacing after another rule each at the last
// nanosecond of their window and at its end. The old tolerance took deliveries 0.9999999995 s
// apart as 1 s apart.
TEST(Judge, EachShapeIsJudgedToTheNanosecond) {
  std::string seen;
  P spacing{P::Kind::Spacing, "PickAndPlace.cmd", "take", 1s, {}, "", "", false, {}};
  EXPECT_TRUE(
      replay_violates(spacing, {deliver(0.5, "take"), deliver(1.499999999, "take")}, &seen));
  EXPECT_FALSE(replay_violates(spacing, {deliver(0.5, "take"), deliver(1.5, "take")}, &seen));
  EXPECT_TRUE(spaced_less_than({Nanos(0), 1s - 1ns}, 1s));
  EXPECT_FALSE(spaced_less_than({Nanos(0), 1s}, 1s));
  P after{P::Kind::Spacing, "HeadControl.gaze", "search", 1s, {}, "", "track", false, {}};
  EXPECT_TRUE(
      replay_violates(after, {deliver(0.2, "track"), deliver(1.199999999, "search")}, &seen));
  EXPECT_FALSE(replay_violates(after, {deliver(0.2, "track"), deliver(1.2, "search")}, &seen));
  // An entry set at 0.2 s until 0.3 s (0.2 + 0.1 in doubles is past 0.3): absent at 0.3 s.
  P absent = absence();
  EXPECT_TRUE(replay_violates(
      absent, {set(0.2, "track", "act_track", 0.3), deliver(0.299999999, "search")}, &seen));
  EXPECT_FALSE(replay_violates(
      absent, {set(0.2, "track", "act_track", 0.3), deliver(0.1 + 0.2, "search")}, &seen));
}

}  // namespace
}  // namespace arbc::verify::temporal
