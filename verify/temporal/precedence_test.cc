// The precedence property `only RULE after OTHER;` (docs/design.md#properties-over-time) on
// the table_clean model: `only put after take` is refuted because the arm's status feed may
// report e_taken at any time (the abstract environment), with or without put's `e_taken`
// guard, and proved by k-induction under the assumption that the arm reports it only after a
// take until a put; a port where only time links the two rules holds to the bound, and loses it
// when the throttle that keeps it goes.
#include "verify/temporal/precedence.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "verify/test_models.h"

namespace arbc::verify::temporal {
namespace {

using namespace std::chrono_literals;

using Outcome = TemporalResult::Outcome;

TemporalResult precedence(const model::App& app, const std::string& port, const std::string& rule,
                          const std::string& other, int bound = 6) {
  z3::context ctx;
  std::string error;
  model::TemporalProperty p{
      model::TemporalProperty::Kind::Precedence, port, rule, 0s, {}, "", "", false, {}};
  p.other = other;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::optional<TemporalResult> r = check_precedence(app, p, bound, ctx, nullptr, deadline, &error);
  EXPECT_TRUE(r) << error;
  return r ? *r : TemporalResult{};
}

int delivery_count(const std::vector<TraceStep>& trace, const std::string& rule) {
  int n = 0;
  for (const TraceStep& s : trace) n += s.delivered && s.connection == rule;
  return n;
}

TEST(Precedence, TheStatusFeedMayReportTakenBeforeAnyTake) {
  TemporalResult r = precedence(testing::table_clean_model(), "PickAndPlace.cmd", "put", "take");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 2u);
  EXPECT_TRUE(r.trace[0].feed);
  EXPECT_NE(std::find(r.trace[0].set.begin(), r.trace[0].set.end(), "e_taken"),
            r.trace[0].set.end());
  EXPECT_EQ(r.trace[1].connection, "put");
  EXPECT_EQ(delivery_count(r.trace, "take"), 0);
}

TEST(Precedence, PutWithoutETakenIsRefutedWithoutTheFeedReportingIt) {
  model::App app = testing::table_clean_model();
  testing::connection(app, "put").constraint = testing::parse("e_arm_idle");
  TemporalResult r = precedence(app, "PickAndPlace.cmd", "put", "take");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 2u);
  EXPECT_EQ(r.trace[1].connection, "put");
  EXPECT_EQ(delivery_count(r.trace, "take"), 0);
}

// HeadControl.gaze edited so that track needs nothing, search needs track's hold (act_track
// present) and is throttled to the hold: each search then needs a track less than 1 s before it,
// hence after the previous search.
model::App search_after_track(std::optional<Nanos> throttle) {
  model::App app = testing::table_clean_model();
  testing::connection(app, "track").constraint = testing::parse("true");
  testing::connection(app, "search").constraint = testing::parse("act_track");
  testing::connection(app, "search").throttle = throttle;
  return app;
}

TEST(Precedence, HoldsToTheBoundWhereTimeLinksTheRules) {
  TemporalResult r = precedence(search_after_track(1s), "HeadControl.gaze", "search", "track");
  // Not proved: k-induction's any state does not link the monitor to the hold's timing (a
  // state "search delivered after the last track, inside its hold" is not reachable with the
  // throttle, but the step case cannot see that), so the verdict stays bounded.
  EXPECT_EQ(r.outcome, Outcome::HoldsToBound);
  EXPECT_EQ(r.induction_k, 0);
  EXPECT_EQ(r.bound, 6);
  EXPECT_TRUE(r.proof.empty());
}

TEST(Precedence, TwoSearchesInsideOneHoldAreTheShortestViolation) {
  TemporalResult r =
      precedence(search_after_track(std::nullopt), "HeadControl.gaze", "search", "track");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 3u);  // track, search, search
  EXPECT_EQ(delivery_count(r.trace, "track"), 1);
  EXPECT_EQ(delivery_count(r.trace, "search"), 2);
  EXPECT_EQ(r.trace[0].connection, "track");
}

model::App with_assumption(const std::string& until) {
  model::App app = testing::table_clean_model();
  app.assumptions.push_back({"e_taken", "PickAndPlace.cmd", "take", until, {}, std::nullopt});
  return app;
}

TEST(Precedence, AnAssumptionAboutTheFeedMakesItProvedByKInduction) {
  // put needs e_taken, which the arm reports only after a take and withdraws after a put.
  TemporalResult r = precedence(with_assumption("put"), "PickAndPlace.cmd", "put", "take");
  ASSERT_EQ(r.outcome, Outcome::Proved);
  EXPECT_EQ(r.induction_k, 1);
  ASSERT_EQ(r.assumptions.size(), 1u);  // printed with the verdict
  EXPECT_EQ(r.assumptions[0].event, "e_taken");
  EXPECT_EQ(r.bound, 6);  // the search went to the bound first
}

TEST(Precedence, WithoutUntilTheArmMayKeepReportingTakenAfterAPut) {
  // `assume e_taken only after take;`: after one take the flag may stay, so two puts follow one
  // take; the trace keeps the assumption (no e_taken before the take delivers).
  TemporalResult r = precedence(with_assumption(""), "PickAndPlace.cmd", "put", "take");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  EXPECT_EQ(delivery_count(r.trace, "take"), 1);
  EXPECT_EQ(delivery_count(r.trace, "put"), 2);
  bool taken = false;
  for (const TraceStep& s : r.trace) {
    bool sets = std::find(s.set.begin(), s.set.end(), "e_taken") != s.set.end();
    EXPECT_TRUE(!sets || taken) << "e_taken set before any take at " << s.time;
    taken |= s.delivered && s.connection == "take";
  }
}

TEST(Precedence, AnAssumptionNamingARuleThePortLacksIsBadInput) {
  z3::context ctx;
  std::string error;
  model::App app = with_assumption("pull");  // pull goes into PullObject.cmd
  model::TemporalProperty p{model::TemporalProperty::Kind::Precedence,
                            "PickAndPlace.cmd",
                            "put",
                            0s,
                            {},
                            "",
                            "take",
                            false,
                            {}};
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  EXPECT_FALSE(check_precedence(app, p, 4, ctx, nullptr, deadline, &error));
  EXPECT_NE(error.find("names rule 'pull', which PickAndPlace.cmd does not have"),
            std::string::npos)
      << error;
}

TEST(Precedence, EitherRuleMissingIsBadInput) {
  z3::context ctx;
  std::string error;
  model::TemporalProperty p{model::TemporalProperty::Kind::Precedence,
                            "PickAndPlace.cmd",
                            "put",
                            0s,
                            {},
                            "",
                            "",
                            false,
                            {}};
  p.other = "pull";  // a rule of PullObject.cmd
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  EXPECT_FALSE(
      check_precedence(testing::table_clean_model(), p, 4, ctx, nullptr, deadline, &error));
  EXPECT_NE(error.find("names rule 'pull', which PickAndPlace.cmd does not have"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace arbc::verify::temporal
