// Response and stability by bounded model checking with environment rates
// (docs/design.md#properties-over-time) on the table_clean model: search resumes within
// track's hold plus LookAround's period only given the rate, a shorter window is refuted
// under the rate, the rate constraints hold in every trace, silence is named, and the head's
// deliverer switches back and forth within a second; an event becoming present opens a window
// that any rule of the port may answer. The replayed runs are judged by
// verify/temporal/judge_response.h, tested here on hand-written records.
#include "verify/temporal/response.h"

#include <gtest/gtest.h>

#include "verify/temporal/judge.h"
#include "verify/temporal/rates.h"
#include "verify/temporal/replay_records_for_tests.h"
#include "verify/temporal/short_bound.h"
#include "verify/temporal/stability.h"
#include "verify/test_models.h"

namespace arbc::verify::temporal {
namespace {

using namespace std::chrono_literals;

using Outcome = TemporalResult::Outcome;
using P = model::TemporalProperty;

P search_resumes(double window) {
  P p{P::Kind::Response,
      "HeadControl.gaze",
      "search",
      nanos_from_seconds(window),
      {},
      "",
      "track",
      true,
      {}};
  p.condition = parse_constraint("e_unreachable and e_arm_idle and e_pull_idle").constraint;
  return p;
}

// table_clean with search's body as the compiler records it for `search: from ...;` (none:
// the message goes through), which accepts every message, and a rate for its source.
model::App with_rate(double period) {
  model::App app = testing::table_clean_model();
  testing::connection(app, "search").body = model::Body{};
  app.rates.push_back({"LookAround.gaze", nanos_from_seconds(period), {"t.spec", 3, 1}});
  return app;
}

TemporalResult check(const model::App& app, const P& p, int bound) {
  z3::context ctx;
  std::string error;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  std::optional<TemporalResult> r =
      p.kind == P::Kind::Response ? check_response(app, p, bound, ctx, nullptr, deadline, &error)
                                  : check_stability(app, p, bound, ctx, nullptr, deadline, &error);
  EXPECT_TRUE(r) << error;
  return r ? *r : TemporalResult{};
}

// Every gap between LookAround.gaze messages in `trace` (from 0, and to `end`) is at most `period`.
void expect_rate_kept(const std::vector<TraceStep>& trace, Nanos period, Nanos end) {
  Nanos last{0};
  for (const TraceStep& s : trace) {
    if (s.source != "LookAround.gaze") continue;
    EXPECT_LE(s.time - last, period) << "a gap before " << s.time.count() << " ns";
    last = s.time;
  }
  EXPECT_LE(end - last, period) << "a gap before the end " << end.count() << " ns";
}

TEST(Response, WithoutARateSilenceViolatesItAndTheReportSaysSo) {
  TemporalResult r = check(testing::table_clean_model(), search_resumes(1.2), 6);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  // The feeds make track's `when` true, track delivers, and nothing more need happen.
  EXPECT_EQ(r.bound, 4);
  EXPECT_TRUE(r.rates.empty());
  EXPECT_NE(r.explanation.find("no rate is given for LookAround.gaze"), std::string::npos)
      << r.explanation;
  EXPECT_NE(r.explanation.find("time reached"), std::string::npos) << r.explanation;
}

TEST(Response, TheHoldPlusThePeriodHoldsGivenTheRate) {
  TemporalResult r = check(with_rate(0.2), search_resumes(1.2), 12);
  EXPECT_EQ(r.outcome, Outcome::HoldsToBound);
  EXPECT_EQ(r.bound, 12);
  ASSERT_EQ(r.rates.size(), 1u);
  EXPECT_EQ(r.rates[0].port, "LookAround.gaze");
}

TEST(Response, AWindowShorterThanTheHoldPlusThePeriodIsRefutedUnderTheRate) {
  TemporalResult r = check(with_rate(0.2), search_resumes(1.1), 12);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  // Three feeds, track, five searches held back, two refreshes of the 0.5 s status events.
  EXPECT_EQ(r.bound, 11);
  Nanos trigger{-1};
  for (const TraceStep& s : r.trace)
    if (s.connection == "track" && s.delivered) trigger = s.time;
  ASSERT_GE(trigger, 0s);
  for (const TraceStep& s : r.trace) {
    if (s.connection == "search") {
      EXPECT_FALSE(s.delivered) << s.time.count();
    }
  }
  expect_rate_kept(r.trace, 200ms, trigger + 1100ms);
  EXPECT_EQ(r.explanation.find("no rate"), std::string::npos) << r.explanation;
}

// With a rate, the bound is also a limit on time: LookAround's messages are due by 0.2 s,
// 0.4 s, ..., so the runs of eight messages last at most 1.8 s, and a window of 1.2 s closes only
// in a run with the six searches due by then and track's delivery.
TEST(Response, TheReportSaysHowLongARunTheBoundCoversAndWhatAWindowNeeds) {
  TemporalResult r = check(with_rate(0.2), search_resumes(1.2), 8);
  ASSERT_EQ(r.outcome, Outcome::HoldsToBound);
  EXPECT_EQ(r.rated_span, 1800ms);
  EXPECT_EQ(r.window_bound, 7);
  EXPECT_FALSE(short_bound_finding(r, false));
}

// Below the window's bound no window closes, whatever the app does: the verdict would hold
// for any app, so a warning (an error with --strict) says so and names the bound to pass.
TEST(Response, ABoundTooSmallForAnyWindowIsAWarningNotAVerdict) {
  TemporalResult r = check(with_rate(0.2), search_resumes(1.2), 6);
  ASSERT_EQ(r.outcome, Outcome::HoldsToBound);
  EXPECT_EQ(r.rated_span, 1400ms);
  std::optional<Finding> f = short_bound_finding(r, false);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->check, kCheckTemporalBound);
  EXPECT_EQ(f->severity, Severity::Warning);
  ASSERT_EQ(f->notes.size(), 1u);
  EXPECT_NE(f->notes[0].message.find("--temporal-bound 7 or more"), std::string::npos)
      << f->notes[0].message;
  std::optional<Finding> strict = short_bound_finding(r, true);
  ASSERT_TRUE(strict);
  EXPECT_EQ(strict->severity, Severity::Error);
  // The same window refuted (1.1 s, eleven messages) is no warning: a violation was found.
  TemporalResult refuted = check(with_rate(0.2), search_resumes(1.1), 12);
  ASSERT_EQ(refuted.outcome, Outcome::Violated);
  EXPECT_FALSE(short_bound_finding(refuted, false));
  EXPECT_EQ(refuted.rated_span, 0s);
}

// Without a rate a source may publish at any times, so no run is too long for the bound.
TEST(Response, WithoutARateNoBoundIsTooShort) {
  TemporalResult r = check(testing::table_clean_model(), search_resumes(1.2), 3);
  EXPECT_EQ(r.window_bound, 0);
  EXPECT_EQ(r.rated_span, 0s);
  EXPECT_FALSE(short_bound_finding(r, false));
}

TEST(Response, AnUnknownRuleIsBadInputNotAVerdict) {
  z3::context ctx;
  std::string error;
  P p = search_resumes(1.2);
  p.other = "trak";
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  EXPECT_FALSE(check_response(testing::table_clean_model(), p, 4, ctx, nullptr, deadline, &error));
  EXPECT_NE(error.find("'trak'"), std::string::npos) << error;
}

// `after e_unreachable, HeadControl.gaze within D while ...`: the object goes out of reach and
// the head must move (track or search) within D, as long as the arm and the rake stay idle.
P head_moves(double window) {
  P p{P::Kind::Response,
      "HeadControl.gaze",
      "",
      nanos_from_seconds(window),
      {},
      "e_unreachable",
      "",
      false,
      {}};
  p.condition = parse_constraint("e_unreachable and e_arm_idle and e_pull_idle").constraint;
  return p;
}

TEST(Response, AnEventBecomingPresentOpensAWindowAndSilenceOfEitherSourceViolatesIt) {
  TemporalResult r = check(testing::table_clean_model(), head_moves(1.0), 6);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_FALSE(r.trace.empty());
  bool set = false;
  for (const TraceStep& s : r.trace)
    for (const std::string& e : s.set) set |= e == "e_unreachable";
  EXPECT_TRUE(set) << "the trigger is the feed setting e_unreachable";
  EXPECT_NE(r.explanation.find("e_unreachable became present at"), std::string::npos)
      << r.explanation;
  // Either rule answers, so both sources are named.
  EXPECT_NE(r.explanation.find("FaceDetector.face, LookAround.gaze"), std::string::npos)
      << r.explanation;
  EXPECT_NE(r.explanation.find("so they may fall silent"), std::string::npos) << r.explanation;
}

TEST(Response, AnyRuleOfThePortAnswers) {
  // Search waits out track's hold (1 s, from a delivery just before the object went out of
  // reach again) and then its next message (every 200 ms), unless track answers first: in time
  // for 1.2 s. Within 0.1 s LookAround need not publish at all.
  model::App app = with_rate(0.2);
  EXPECT_EQ(check(app, head_moves(1.2), 10).outcome, Outcome::HoldsToBound);
  TemporalResult r = check(app, head_moves(0.1), 10);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  // LookAround has a rate, so silence of FaceDetector alone is no explanation.
  EXPECT_EQ(r.explanation.find("no rate"), std::string::npos) << r.explanation;
  P only_search = head_moves(1.2);
  only_search.rule = "search";
  EXPECT_EQ(check(app, only_search, 10).outcome, Outcome::HoldsToBound);
}

TEST(Response, ATriggerEventNothingSetsIntoThePortIsVacuousNotProved) {
  P p = head_moves(1.0);
  p.event = "e_taken";  // fed into PickAndPlace.cmd, not into HeadControl.gaze
  TemporalResult r = check(testing::table_clean_model(), p, 4);
  EXPECT_EQ(r.outcome, Outcome::Vacuous);
  EXPECT_NE(r.proof.find("never becomes present there"), std::string::npos) << r.proof;
}

TEST(Stability, TheHeadSwitchesBackAndForthWithinTheHold) {
  P p{P::Kind::Stability, "HeadControl.gaze", "", 1500ms, {}, "", "", false, {}};
  // Under the rate the shortest violation takes 12 messages: the three feeds, then LookAround's
  // messages every 200 ms around track's deliveries (arbc verify --temporal-bound 12 finds it).
  TemporalResult r = check(with_rate(0.2), p, 12);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  EXPECT_EQ(r.bound, 12);
  std::vector<std::pair<Nanos, std::string>> delivered;
  for (const TraceStep& s : r.trace)
    if (s.delivered) delivered.emplace_back(s.time, s.connection);
  ASSERT_GE(delivered.size(), 3u);
  std::vector<Nanos> switches;
  for (size_t i = 1; i < delivered.size(); ++i)
    if (delivered[i].second != delivered[i - 1].second) switches.push_back(delivered[i].first);
  ASSERT_GE(switches.size(), 2u);
  EXPECT_LT(switches.back() - switches[switches.size() - 2], 1500ms);
  expect_rate_kept(r.trace, 200ms, r.trace.back().time);
}

TEST(Stability, AOneRulePortNeverSwitches) {
  P p{P::Kind::Stability, "Speak.text", "", 10s, {}, "", "", false, {}};
  EXPECT_EQ(check(testing::table_clean_model(), p, 5).outcome, Outcome::HoldsToBound);
}

TEST(Rates, OnlyRulesThatCannotFailAcceptEveryMessage) {
  model::Connection c;
  c.kind = model::ConnectionKind::Rule;
  EXPECT_FALSE(accepts_every_message(c));  // no body recorded: not known
  c.body = model::Body{};
  EXPECT_TRUE(accepts_every_message(c));
  model::BodyStmt emit;
  emit.kind = model::BodyStmt::Kind::Emit;
  emit.expr.op = model::BodyExpr::Op::Field;
  emit.expr.text = "pos";
  emit.expr.args.resize(1);
  emit.expr.args[0].op = model::BodyExpr::Op::Message;
  c.body->push_back(emit);
  EXPECT_TRUE(accepts_every_message(c));  // `emit face.pos;`
  model::BodyStmt accept;
  accept.kind = model::BodyStmt::Kind::Accept;
  c.body->push_back(accept);
  EXPECT_FALSE(accepts_every_message(c));
  c.body->pop_back();
  c.body->back().expr.op = model::BodyExpr::Op::Index;  // may be out of range: a monitor error
  EXPECT_FALSE(accepts_every_message(c));
  c.body->back().expr.op = model::BodyExpr::Op::Message;
  c.opaque = true;  // a script
  EXPECT_FALSE(accepts_every_message(c));
}

using namespace records;  // at, deliver, set, drop: records written in seconds

TEST(JudgeResponse, AnUnansweredTriggerViolatesAndADeliveryAtTheWindowsEndAnswers) {
  P p{P::Kind::Response, "HeadControl.gaze", "search", 1s, {}, "", "track", true, {}};
  std::string seen;
  EXPECT_TRUE(replay_violates(p, {deliver(0, "track"), drop(0.5, "search")}, &seen));
  EXPECT_FALSE(replay_violates(p, {deliver(0, "track"), deliver(1.0, "search")}, &seen));
  // Too late, but a later track (stops) starts a new window that is unanswered too.
  EXPECT_TRUE(replay_violates(p, {deliver(0, "track"), deliver(1.5, "search")}, &seen));
  EXPECT_FALSE(replay_violates(
      p, {deliver(0, "track"), deliver(0.5, "track"), deliver(1.4, "search")}, &seen));
  EXPECT_NE(seen.find("track at 0s"), std::string::npos) << seen;
}

TEST(JudgeResponse, TheConditionFalseWhenTheRuleDecidesDischargesTheWindow) {
  P p{P::Kind::Response, "HeadControl.gaze", "search", 1s, {}, "", "track", true, {}};
  p.condition = Constraint::event_ref("e_idle");
  std::string seen;
  // e_idle until 0.5: false when search decides at 0.8, so search owed nothing.
  EXPECT_FALSE(replay_violates(p,
                               {set(0, "feed", "e_idle", 0.5), deliver(0, "track"),
                                drop(0.2, "search"), drop(0.8, "search")},
                               &seen));
  EXPECT_TRUE(replay_violates(
      p,
      {set(0, "feed", "e_idle", 2), deliver(0, "track"), drop(0.2, "search"), drop(0.8, "search")},
      &seen));
  // Only the rule's decisions count: track deciding at 0.8 discharges nothing.
  EXPECT_TRUE(replay_violates(
      p, {set(0, "feed", "e_idle", 0.5), deliver(0, "track"), drop(0.8, "track")}, &seen));
  // A decision before the trigger, at the same instant, is not in its window.
  EXPECT_TRUE(replay_violates(
      p, {drop(0, "search"), set(0, "feed", "e_idle", 2), deliver(0, "track")}, &seen));
}

ReplayRecord lapse(double t, const std::string& owner, const std::string& e, double expiry) {
  return records::remove(t, owner, e, expiry);
}

TEST(JudgeResponse, AnEventsOnsetOpensAWindowThatAnyRuleOfThePortAnswers) {
  P p{P::Kind::Response, "HeadControl.gaze", "", 1s, {}, "e_lost", "", false, {}};
  std::string seen;
  EXPECT_TRUE(replay_violates(p, {set(0, "feed", "e_lost", 5)}, &seen));
  EXPECT_FALSE(replay_violates(p, {set(0, "feed", "e_lost", 5), deliver(0.9, "search")}, &seen));
  EXPECT_FALSE(replay_violates(p, {set(0, "feed", "e_lost", 5), deliver(1.0, "track")}, &seen));
  // A refresh while present is no onset; a set after the lapse is one, and goes unanswered.
  EXPECT_FALSE(replay_violates(
      p, {set(0, "feed", "e_lost", 0.5), deliver(0.2, "track"), set(0.4, "feed", "e_lost", 0.9)},
      &seen));
  EXPECT_TRUE(replay_violates(p,
                              {set(0, "feed", "e_lost", 0.5), deliver(0.2, "track"),
                               lapse(0.5, "feed", "e_lost", 0.5), set(0.6, "feed", "e_lost", 2)},
                              &seen));
  EXPECT_NE(seen.find("e_lost present at 0s"), std::string::npos) << seen;
  // A trigger rule of the port does not answer its own delivery, only a later one.
  P after_track{P::Kind::Response, "HeadControl.gaze", "", 1s, {}, "", "track", false, {}};
  EXPECT_TRUE(replay_violates(after_track, {deliver(0, "track")}, &seen));
  EXPECT_FALSE(replay_violates(after_track, {deliver(0, "track"), deliver(0.5, "search")}, &seen));
  // Its next delivery answers the first window and opens another.
  EXPECT_TRUE(replay_violates(after_track, {deliver(0, "track"), deliver(0.5, "track")}, &seen));
  // Only the named rule answers when the property names one.
  p.rule = "search";
  EXPECT_TRUE(replay_violates(p, {set(0, "feed", "e_lost", 5), deliver(0.5, "track")}, &seen));
}

TEST(JudgeStability, TwoSwitchesWithinTheWindowViolate) {
  P p{P::Kind::Stability, "HeadControl.gaze", "", 1s, {}, "", "", false, {}};
  std::string seen;
  EXPECT_TRUE(replay_violates(
      p, {deliver(0, "search"), deliver(0.2, "track"), deliver(1.1, "search")}, &seen));
  EXPECT_FALSE(replay_violates(
      p, {deliver(0, "search"), deliver(0.2, "track"), deliver(1.2, "search")}, &seen));
  EXPECT_FALSE(replay_violates(p, {deliver(0, "search"), deliver(0.1, "search")}, &seen));
  // Exactly, to the nanosecond: switches the window apart are fine, a nanosecond less is not.
  EXPECT_FALSE(replay_violates(
      p, {deliver(0, "search"), deliver(0.2, "track"), deliver(1.2, "search")}, &seen));
  EXPECT_TRUE(replay_violates(
      p, {deliver(0, "search"), deliver(0.2, "track"), deliver(1.199999999, "search")}, &seen));
}

// A response's window ends at its last nanosecond: an answer exactly the window after the
// trigger is in time, one a nanosecond later is not (docs/design.md#properties-over-time).
TEST(JudgeResponse, TheWindowEndsExactlyAtItsLastNanosecond) {
  P p{P::Kind::Response, "HeadControl.gaze", "search", 1s, {}, "", "track", false, {}};
  std::string seen;
  EXPECT_FALSE(replay_violates(p, {deliver(0.3, "track"), deliver(1.3, "search")}, &seen));
  EXPECT_TRUE(replay_violates(p, {deliver(0.3, "track"), deliver(1.300000001, "search")}, &seen));
}

}  // namespace
}  // namespace arbc::verify::temporal
