// The spacing property by bounded model checking (docs/design.md#properties-over-time) on the
// table_clean model: a rule without a throttle is refuted with a shortest timed trace, a
// throttle at least the window proves it for runs of any length, a shorter one does not; a
// rule after another is kept out by a hold as long as the window, not by a shorter one.
#include "verify/temporal/spacing.h"

#include <gtest/gtest.h>

#include "verify/test_models.h"

namespace arbc::verify::temporal {

using namespace std::chrono_literals;
namespace {

using Outcome = TemporalResult::Outcome;

TemporalResult spacing(const model::App& app, const std::string& port, const std::string& rule,
                       Nanos window, int bound = 6) {
  z3::context ctx;
  std::string error;
  model::TemporalProperty p{
      model::TemporalProperty::Kind::Spacing, port, rule, window, {}, "", "", false, {}};
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::optional<TemporalResult> r = check_spacing(app, p, bound, ctx, nullptr, deadline, &error);
  EXPECT_TRUE(r) << error;
  return r ? *r : TemporalResult{};
}

// The deliveries of `rule` in `trace`, by time.
std::vector<Nanos> deliveries(const std::vector<TraceStep>& trace, const std::string& rule) {
  std::vector<Nanos> out;
  for (const TraceStep& s : trace)
    if (s.delivered && s.connection == rule) out.push_back(s.time);
  return out;
}

TEST(Spacing, TakeWithoutThrottleIsRefutedByTheShortestTrace) {
  TemporalResult r = spacing(testing::table_clean_model(), "PickAndPlace.cmd", "take", 1s);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  // The two status feeds make the arm and the rake idle, then two objects arrive.
  ASSERT_EQ(r.bound, 4);
  ASSERT_EQ(r.trace.size(), 4u);
  std::vector<Nanos> takes = deliveries(r.trace, "take");
  ASSERT_EQ(takes.size(), 2u);
  EXPECT_LT(takes[1] - takes[0], 1s);
  EXPECT_TRUE(r.trace.back().delivered);
  for (size_t k = 1; k < r.trace.size(); ++k) EXPECT_GE(r.trace[k].time, r.trace[k - 1].time);
  int feeds_setting = 0;
  for (const TraceStep& s : r.trace) feeds_setting += !s.set.empty() && !s.delivered;
  EXPECT_EQ(feeds_setting, 2);
}

TEST(Spacing, ThrottleAtLeastTheWindowIsProvedAfterTheSearchFindsNothing) {
  model::App app = testing::table_clean_model();
  ASSERT_TRUE(testing::connection(app, "ask").throttle);
  Nanos period = *testing::connection(app, "ask").throttle;
  for (Nanos window : {period, period / 2, period - 1ns}) {
    TemporalResult r = spacing(app, "Speak.text", "ask", window);
    EXPECT_EQ(r.outcome, Outcome::Proved) << window.count();
    EXPECT_NE(r.proof.find("`throttle 5s;`"), std::string::npos) << r.proof;
    EXPECT_EQ(r.bound, 6);  // the search ran to the bound as well
    EXPECT_TRUE(r.trace.empty());
  }
}

TEST(Spacing, AWindowLongerThanTheThrottleIsRefutedAtThePeriod) {
  model::App app = testing::table_clean_model();
  Nanos period = *testing::connection(app, "ask").throttle;
  TemporalResult r = spacing(app, "Speak.text", "ask", period + 500ms);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  std::vector<Nanos> asks = deliveries(r.trace, "ask");
  ASSERT_EQ(asks.size(), 2u);
  EXPECT_GE(asks[1] - asks[0], period);  // the throttle still holds in the trace
  EXPECT_LT(asks[1] - asks[0], period + 500ms);
}

// The throttle's own period is read exactly, in nanoseconds (core/instant.h): a window one
// nanosecond longer is violated by two deliveries exactly the period apart, which the runtime
// lets through (it drops only those less than the period apart).
TEST(Spacing, AWindowOneNanosecondLongerThanTheThrottleIsRefutedExactlyAtThePeriod) {
  model::App app = testing::table_clean_model();
  Nanos period = *testing::connection(app, "ask").throttle;
  TemporalResult r = spacing(app, "Speak.text", "ask", period + 1ns);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  std::vector<Nanos> asks = deliveries(r.trace, "ask");
  ASSERT_EQ(asks.size(), 2u);
  EXPECT_EQ(asks[1] - asks[0], period);
}

TEST(Spacing, RemovingTheThrottleRefutesIt) {
  model::App app = testing::table_clean_model();
  Nanos period = *testing::connection(app, "ask").throttle;
  testing::connection(app, "ask").throttle.reset();
  EXPECT_EQ(spacing(app, "Speak.text", "ask", period).outcome, Outcome::Violated);
}

TEST(Spacing, AnActivityEventLapsesAtTheEndOfTheHold) {
  // track reading its own activity event: it can deliver again exactly when its 1 s hold
  // lapses (absent at the expiry instant, docs/design.md#events-and-lifetimes), not before.
  model::App app = testing::table_clean_model();
  testing::connection(app, "track").constraint = testing::parse("not act_track");
  // Not a throttle: k-induction proves it (any state's hold ends one hold after the last track).
  TemporalResult proved = spacing(app, "HeadControl.gaze", "track", 1s);
  EXPECT_EQ(proved.outcome, Outcome::Proved);
  EXPECT_EQ(proved.induction_k, 1);
  TemporalResult r = spacing(app, "HeadControl.gaze", "track", 1250ms);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  std::vector<Nanos> tracks = deliveries(r.trace, "track");
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_GE(tracks[1] - tracks[0], 1s);
  // A window a nanosecond past the hold: two tracks exactly the hold apart.
  TemporalResult edge = spacing(app, "HeadControl.gaze", "track", 1s + 1ns);
  ASSERT_EQ(edge.outcome, Outcome::Violated);
  tracks = deliveries(edge.trace, "track");
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[1] - tracks[0], 1s);
  // Without the hold's effect (the rule reads nothing), two deliveries may share an instant.
  testing::connection(app, "track").constraint = testing::parse("true");
  EXPECT_EQ(spacing(app, "HeadControl.gaze", "track", 1s).outcome, Outcome::Violated);
}

TemporalResult check_after(const model::App& app, const std::string& rule, const std::string& other,
                           Nanos window) {
  z3::context ctx;
  std::string error;
  model::TemporalProperty p{model::TemporalProperty::Kind::Spacing,
                            "HeadControl.gaze",
                            rule,
                            window,
                            {},
                            "",
                            other,
                            false,
                            {}};
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  // Eight messages, as `arbc verify` explores by default: a search a hold after track needs
  // the three feeds, track, the two status feeds again (their flags lapse in 0.5 s) and search.
  std::optional<TemporalResult> r = check_spacing(app, p, 8, ctx, nullptr, deadline, &error);
  EXPECT_TRUE(r) << error;
  return r ? *r : TemporalResult{};
}

TEST(Spacing, AfterAnotherRuleTheHoldKeepsTheLowerRuleOutForItsLength) {
  // `never search within W after track;`: track's 1 s hold keeps search out for 1 s.
  model::App app = testing::table_clean_model();
  EXPECT_NE(check_after(app, "search", "track", 1s).outcome, Outcome::Violated);
  TemporalResult r = check_after(app, "search", "track", 1250ms);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  std::vector<Nanos> tracks = deliveries(r.trace, "track");
  std::vector<Nanos> searches = deliveries(r.trace, "search");
  ASSERT_EQ(tracks.size(), 1u);
  ASSERT_EQ(searches.size(), 1u);
  EXPECT_GE(searches[0] - tracks[0], 1s);
  EXPECT_LT(searches[0] - tracks[0], 1250ms);
  EXPECT_TRUE(r.trace.back().delivered);
  EXPECT_EQ(r.trace.back().connection, "search");
}

TEST(Spacing, AfterAnotherRuleAShorterHoldIsRefuted) {
  model::App app = testing::table_clean_model();
  for (model::Event& e : app.events)
    if (e.name == "act_track") e.lifetime = 500ms;
  TemporalResult r = check_after(app, "search", "track", 1s);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  std::vector<Nanos> tracks = deliveries(r.trace, "track");
  std::vector<Nanos> searches = deliveries(r.trace, "search");
  ASSERT_EQ(searches.size(), 1u);
  ASSERT_FALSE(tracks.empty());
  EXPECT_GE(searches[0] - tracks.back(), 500ms);
  EXPECT_LT(searches[0] - tracks.back(), 1s);
  // The other way round nothing keeps them apart: track, first by priority, may follow search
  // at once.
  EXPECT_EQ(check_after(app, "track", "search", 1s).outcome, Outcome::Violated);
}

TEST(Spacing, UnknownRuleIsBadInputNotAVerdict) {
  z3::context ctx;
  std::string error;
  model::TemporalProperty p{model::TemporalProperty::Kind::Spacing,
                            "PickAndPlace.cmd",
                            "pull",
                            1s,
                            {},
                            "",
                            "",
                            false,
                            {}};
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  EXPECT_FALSE(check_spacing(testing::table_clean_model(), p, 4, ctx, nullptr, deadline, &error));
  EXPECT_NE(error.find("does not have"), std::string::npos) << error;
}

}  // namespace
}  // namespace arbc::verify::temporal
