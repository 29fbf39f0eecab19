// The absence property `never RULE while EVENT;` (docs/design.md#properties-over-time) on the
// table_clean model: proved at a single decision where the rule's constraint excludes the
// event (a `by priority` hold, a `not e` in the guard) or nothing sets the event into the port;
// refuted with a shortest timed trace where it is not; bounded where only time keeps it.
#include "verify/temporal/absence.h"

#include <gtest/gtest.h>

#include "verify/temporal/short_bound.h"
#include "verify/test_models.h"

namespace arbc::verify::temporal {

using namespace std::chrono_literals;
namespace {

using Outcome = TemporalResult::Outcome;

TemporalResult absence(const model::App& app, const std::string& port, const std::string& rule,
                       const std::string& event, int bound = 6) {
  z3::context ctx;
  std::string error;
  model::TemporalProperty p{
      model::TemporalProperty::Kind::Absence, port, rule, 0s, {}, "", "", false, {}};
  p.event = event;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::optional<TemporalResult> r = check_absence(app, p, bound, ctx, nullptr, deadline, &error);
  EXPECT_TRUE(r) << error;
  return r ? *r : TemporalResult{};
}

TEST(Absence, APriorityHoldIsProvedAtEveryDecision) {
  TemporalResult r =
      absence(testing::table_clean_model(), "HeadControl.gaze", "search", "act_track");
  EXPECT_EQ(r.outcome, Outcome::Proved);
  EXPECT_NE(r.proof.find("false whenever act_track is present"), std::string::npos) << r.proof;
  EXPECT_EQ(r.bound, 6);  // the search ran to the bound as well
}

TEST(Absence, WithoutTheHoldsTermSearchDeliversInsideTracksHold) {
  model::App app = testing::table_clean_model();
  testing::connection(app, "search").constraint =
      testing::parse("e_unreachable and e_arm_idle and e_pull_idle");
  TemporalResult r = absence(app, "HeadControl.gaze", "search", "act_track");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  // Three feeds make both rules' events present, track delivers, search delivers.
  ASSERT_EQ(r.bound, 5);
  ASSERT_EQ(r.trace.size(), 5u);
  Nanos track_at{-1};
  for (const TraceStep& s : r.trace)
    if (s.delivered && s.connection == "track") track_at = s.time;
  ASSERT_GE(track_at, 0s);
  EXPECT_EQ(r.trace.back().connection, "search");
  EXPECT_TRUE(r.trace.back().delivered);
  EXPECT_LT(r.trace.back().time, track_at + 1s);  // inside the 1 s hold
}

TEST(Absence, AGuardThatNeedsTheEventIsRefutedInTwoMessages) {
  // put needs e_taken: the status feed sets it (with e_arm_idle), and put delivers.
  TemporalResult r = absence(testing::table_clean_model(), "PickAndPlace.cmd", "put", "e_taken");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 2u);
  EXPECT_TRUE(r.trace[0].feed);
  EXPECT_EQ(r.trace[1].connection, "put");
  // take's `not e_taken` excludes it at every decision.
  EXPECT_EQ(absence(testing::table_clean_model(), "PickAndPlace.cmd", "take", "e_taken").outcome,
            Outcome::Proved);
}

TEST(Absence, AnEventNothingSetsIntoThePortIsVacuousNotProved) {
  // e_face_detected is fed into Speak.text only: PickAndPlace.cmd's container never holds it,
  // so the property is true of every run and says nothing (docs/checks.md#vacuous).
  TemporalResult r =
      absence(testing::table_clean_model(), "PickAndPlace.cmd", "take", "e_face_detected");
  EXPECT_EQ(r.outcome, Outcome::Vacuous);
  std::optional<Finding> f = vacuous_finding(testing::table_clean_model(), r, false);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->severity, Severity::Warning);
  EXPECT_NE(f->notes[0].message.find("Speak.text"), std::string::npos) << f->notes[0].message;
  EXPECT_EQ(vacuous_finding(testing::table_clean_model(), r, true)->severity, Severity::Error);
  EXPECT_NE(r.proof.find("no connection into PickAndPlace.cmd sets e_face_detected"),
            std::string::npos)
      << r.proof;
  // A `script` rule into the port might set it: no proof then, only the bound.
  model::App app = testing::table_clean_model();
  testing::connection(app, "put").opaque = true;
  EXPECT_EQ(absence(app, "PickAndPlace.cmd", "take", "e_face_detected").outcome,
            Outcome::HoldsToBound);
}

TEST(Absence, WhatOnlyTimeKeepsIsProvedByKInductionNotAtOneDecision) {
  // track inside its own hold: its constraint does not exclude act_track (present at its
  // decision when it delivered less than 1 s ago), so no single decision proves it; a throttle
  // of 1 s keeps every run clean, and k-induction proves it (from any state the hold ends one
  // hold after the last delivery, which the throttle outlasts); a shorter one does not.
  model::App app = testing::table_clean_model();
  // Without its events (the status feeds' flags lapse after 0.5 s, which would need more
  // messages to refresh them than the bound gives).
  testing::connection(app, "track").constraint = testing::parse("true");
  testing::connection(app, "track").throttle = 1s;
  TemporalResult proved = absence(app, "HeadControl.gaze", "track", "act_track");
  EXPECT_EQ(proved.outcome, Outcome::Proved);
  EXPECT_EQ(proved.induction_k, 1);
  EXPECT_NE(proved.proof.find("k-induction with k = 1"), std::string::npos) << proved.proof;
  testing::connection(app, "track").throttle = 500ms;
  TemporalResult r = absence(app, "HeadControl.gaze", "track", "act_track");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 2u);  // track, then track again 0.5 s later, inside the hold
  EXPECT_GE(r.trace[1].time - r.trace[0].time, 500ms);
  EXPECT_LT(r.trace[1].time - r.trace[0].time, 1s);
  // A throttle one nanosecond short of the hold: the second track at its hold's last
  // nanosecond (core/instant.h), still inside it.
  testing::connection(app, "track").throttle = 1s - 1ns;
  r = absence(app, "HeadControl.gaze", "track", "act_track");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 2u);
  EXPECT_EQ(r.trace[1].time - r.trace[0].time, 1s - 1ns);
}

TEST(Absence, UnknownRuleIsBadInputNotAVerdict) {
  z3::context ctx;
  std::string error;
  model::TemporalProperty p{model::TemporalProperty::Kind::Absence,
                            "PickAndPlace.cmd",
                            "pull",
                            0s,
                            {},
                            "",
                            "",
                            false,
                            {}};
  p.event = "e_taken";
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  EXPECT_FALSE(check_absence(testing::table_clean_model(), p, 4, ctx, nullptr, deadline, &error));
  EXPECT_NE(error.find("does not have"), std::string::npos) << error;
}

}  // namespace
}  // namespace arbc::verify::temporal
