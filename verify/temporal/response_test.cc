// Response and stability by bounded model checking with environment rates
// (docs/design.md#properties-over-time) on the table_clean model: search resumes within
// track's hold plus LookAround's period only given the rate, a shorter window is refuted
// under the rate, the rate constraints hold in every trace, silence is named, and the head's
// deliverer switches back and forth within a second. The replayed runs are judged by
// verify/temporal/judge_response.h, tested here on hand-written records.
#include "verify/temporal/response.h"

#include <gtest/gtest.h>

#include "verify/temporal/judge.h"
#include "verify/temporal/rates.h"
#include "verify/temporal/stability.h"
#include "verify/test_models.h"

namespace arbc::verify::temporal {
namespace {

using Outcome = TemporalResult::Outcome;
using P = model::TemporalProperty;

P search_resumes(double window) {
  P p{P::Kind::Response, "HeadControl.gaze", "search", window, {}, "", "track", true, {}};
  p.condition = parse_constraint("e_unreachable and e_arm_idle and e_pull_idle").constraint;
  return p;
}

// table_clean with search's body as the compiler records it for `search: from ...;` (none:
// the message goes through), which accepts every message, and a rate for its source.
model::App with_rate(double period) {
  model::App app = testing::table_clean_model();
  testing::connection(app, "search").body = model::Body{};
  app.rates.push_back({"LookAround.gaze", period, {"t.spec", 3, 1}});
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
void expect_rate_kept(const std::vector<TraceStep>& trace, double period, double end) {
  double last = 0;
  for (const TraceStep& s : trace) {
    if (s.source != "LookAround.gaze") continue;
    EXPECT_LE(s.time - last, period + 1e-9) << "a gap before " << s.time;
    last = s.time;
  }
  EXPECT_LE(end - last, period + 1e-9) << "a gap before the end " << end;
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
  double trigger = -1;
  for (const TraceStep& s : r.trace)
    if (s.connection == "track" && s.delivered) trigger = s.time;
  ASSERT_GE(trigger, 0);
  for (const TraceStep& s : r.trace) {
    if (s.connection == "search") {
      EXPECT_FALSE(s.delivered) << s.time;
    }
  }
  expect_rate_kept(r.trace, 0.2, trigger + 1.1);
  EXPECT_EQ(r.explanation.find("no rate"), std::string::npos) << r.explanation;
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

TEST(Stability, TheHeadSwitchesBackAndForthWithinTheHold) {
  P p{P::Kind::Stability, "HeadControl.gaze", "", 1.5, {}, "", "", false, {}};
  // Under the rate the shortest violation takes 12 messages: the three feeds, then LookAround's
  // messages every 200 ms around track's deliveries (arbc verify --temporal-bound 12 finds it).
  TemporalResult r = check(with_rate(0.2), p, 12);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  EXPECT_EQ(r.bound, 12);
  std::vector<std::pair<double, std::string>> delivered;
  for (const TraceStep& s : r.trace)
    if (s.delivered) delivered.emplace_back(s.time, s.connection);
  ASSERT_GE(delivered.size(), 3u);
  std::vector<double> switches;
  for (size_t i = 1; i < delivered.size(); ++i)
    if (delivered[i].second != delivered[i - 1].second) switches.push_back(delivered[i].first);
  ASSERT_GE(switches.size(), 2u);
  EXPECT_LT(switches.back() - switches[switches.size() - 2], 1.5);
  expect_rate_kept(r.trace, 0.2, r.trace.back().time);
}

TEST(Stability, AOneRulePortNeverSwitches) {
  P p{P::Kind::Stability, "Speak.text", "", 10, {}, "", "", false, {}};
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

using K = ReplayRecord::Kind;
ReplayRecord deliver(double t, const std::string& rule) { return {K::Deliver, t, rule, "", -1}; }
ReplayRecord set(double t, const std::string& owner, const std::string& e, double expiry) {
  return {K::Set, t, owner, e, expiry};
}

model::TestCase inputs(const std::vector<double>& times) {
  model::TestCase test;
  for (double t : times) {
    model::TestStep s;
    s.t = t;
    s.port = "LookAround.gaze";
    test.steps.push_back(s);
  }
  return test;
}

TEST(JudgeResponse, AnUnansweredTriggerViolatesAndADeliveryAtTheWindowsEndAnswers) {
  P p{P::Kind::Response, "HeadControl.gaze", "search", 1.0, {}, "", "track", true, {}};
  std::string seen;
  model::TestCase test = inputs({0.5});
  EXPECT_TRUE(replay_violates(p, {deliver(0, "track")}, &seen, &test, "LookAround.gaze"));
  EXPECT_FALSE(replay_violates(p, {deliver(0, "track"), deliver(1.0, "search")}, &seen, &test,
                               "LookAround.gaze"));
  // Too late, but a later track (stops) starts a new window that is unanswered too.
  EXPECT_TRUE(replay_violates(p, {deliver(0, "track"), deliver(1.5, "search")}, &seen, &test,
                              "LookAround.gaze"));
  EXPECT_FALSE(replay_violates(p,
                               {deliver(0, "track"), deliver(0.5, "track"), deliver(1.4, "search")},
                               &seen, &test, "LookAround.gaze"));
  EXPECT_NE(seen.find("track at 0s"), std::string::npos) << seen;
}

TEST(JudgeResponse, TheConditionFalseAtADecisionDischargesTheWindow) {
  P p{P::Kind::Response, "HeadControl.gaze", "search", 1.0, {}, "", "track", true, {}};
  p.condition = Constraint::event_ref("e_idle");
  std::string seen;
  model::TestCase test = inputs({0.2, 0.8});
  // e_idle until 0.5: false at the decision at 0.8, so search owed nothing.
  EXPECT_FALSE(replay_violates(p, {set(0, "feed", "e_idle", 0.5), deliver(0, "track")}, &seen,
                               &test, "LookAround.gaze"));
  EXPECT_TRUE(replay_violates(p, {set(0, "feed", "e_idle", 2), deliver(0, "track")}, &seen, &test,
                              "LookAround.gaze"));
}

TEST(JudgeStability, TwoSwitchesWithinTheWindowViolate) {
  P p{P::Kind::Stability, "HeadControl.gaze", "", 1.0, {}, "", "", false, {}};
  std::string seen;
  EXPECT_TRUE(replay_violates(
      p, {deliver(0, "search"), deliver(0.2, "track"), deliver(1.1, "search")}, &seen));
  EXPECT_FALSE(replay_violates(
      p, {deliver(0, "search"), deliver(0.2, "track"), deliver(1.2, "search")}, &seen));
  EXPECT_FALSE(replay_violates(p, {deliver(0, "search"), deliver(0.1, "search")}, &seen));
}

}  // namespace
}  // namespace arbc::verify::temporal
