// The port's own delivery events in the temporal model (verify/temporal/own_delivery.h), on
// table_clean with the arm's two delivery events fed into PickAndPlace.cmd itself:
// e_arm_picking (`cmd.verb != "cancel" for 1s`) and e_take_open (`cmd.verb == "take"`). take's
// constant verb sets both, so `never two take within 1s` and `only put after take` are proved
// with no assumption about the arm; a take that may emit "cancel" leaves e_arm_picking free at
// its delivery, and a put that does not read e_take_open is refuted. Where the verb comes from
// the data, the solver decides (DataQuery::predicate_range), and a counterexample's message
// makes the delivery do what its trace says.
#include "verify/temporal/own_delivery.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/body_text.h"
#include "verify/temporal/counterexample.h"
#include "verify/temporal/precedence.h"
#include "verify/temporal/spacing.h"
#include "verify/test_models.h"

namespace arbc::verify::temporal {
namespace {

using namespace std::chrono_literals;
using Outcome = TemporalResult::Outcome;

model::BodyStmt stmt(const std::string& text) {
  std::string err;
  std::optional<model::BodyStmt> s = model::parse_body_stmt(text, &err);
  if (!s) throw std::runtime_error("bad body in a test: " + text + ": " + err);
  return *s;
}

model::Event delivery_event(const std::string& name, const std::string& predicate,
                            std::optional<Nanos> lifetime) {
  model::Event e;
  e.name = name;
  e.source = "PickAndPlace.cmd";
  e.lifetime = lifetime;
  std::string err;
  e.predicate = model::parse_body_expr(predicate, &err);
  if (!e.predicate) throw std::runtime_error("bad predicate in a test: " + err);
  return e;
}

// table_clean with the arm's delivery events read by PickAndPlace.cmd's own rules, which emit
// their verbs as constants.
model::App own_events() {
  model::App app = testing::table_clean_model();
  app.events.push_back(
      delivery_event("e_arm_picking", "(!= (field verb msg) \"cancel\")", Nanos(1s)));
  app.events.push_back(delivery_event("e_take_open", "(== (field verb msg) \"take\")", {}));
  model::Connection feed;
  feed.name = "feed_PickAndPlace_cmd";
  feed.source = feed.destination = "PickAndPlace.cmd";
  feed.kind = model::ConnectionKind::Feed;
  feed.generated = true;
  feed.constraint = Constraint::constant(false);
  feed.sets = {"e_arm_picking", "e_take_open"};
  feed.unsets = {"e_take_open"};
  app.connections.push_back(feed);
  model::Connection& take = testing::connection(app, "take");
  take.constraint =
      testing::parse("not e_taken and e_arm_idle and e_pull_idle and not e_arm_picking");
  take.body = model::Body{stmt("(emit 41 (record verb \"take\" pos (call vec3 0.0 0.0 0.0)))")};
  model::Connection& put = testing::connection(app, "put");
  put.constraint = testing::parse("e_taken and e_take_open and e_arm_idle and not e_arm_picking");
  put.body = model::Body{stmt("(emit 44 (record verb \"put\" pos msg))")};
  return app;
}

model::TemporalProperty property(model::TemporalProperty::Kind kind, const std::string& rule,
                                 const std::string& other, Nanos window) {
  model::TemporalProperty p{kind, "PickAndPlace.cmd", rule, window, {}, "", "", false, {}};
  p.other = other;
  return p;
}

TemporalResult check(const model::App& app, const model::TemporalProperty& p,
                     DataQuery* data = nullptr) {
  z3::context ctx;
  std::string error;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::optional<TemporalResult> r = p.kind == model::TemporalProperty::Kind::Spacing
                                        ? check_spacing(app, p, 6, ctx, data, deadline, &error)
                                        : check_precedence(app, p, 6, ctx, data, deadline, &error);
  EXPECT_TRUE(r) << error;
  return r ? *r : TemporalResult{};
}

TemporalResult two_takes(const model::App& app) {
  return check(app, property(model::TemporalProperty::Kind::Spacing, "take", "", 1s));
}

TemporalResult put_after_take(const model::App& app) {
  return check(app, property(model::TemporalProperty::Kind::Precedence, "put", "take", 0s));
}

bool lists(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// No step of the trace is the environment setting an own delivery event.
void expect_only_deliveries_set(const TemporalResult& r) {
  for (const TraceStep& s : r.trace) {
    if (!s.feed) continue;
    EXPECT_FALSE(lists(s.set, "e_arm_picking")) << s.connection;
    EXPECT_FALSE(lists(s.set, "e_take_open")) << s.connection;
  }
}

TEST(OwnDelivery, ConstantVerbsDecideTheEvents) {
  model::App app = own_events();
  const model::Event& picking = app.events[app.events.size() - 2];
  const model::Event& open = app.events.back();
  EXPECT_EQ(constant_outcome(testing::connection(app, "take"), *picking.predicate), true);
  EXPECT_EQ(constant_outcome(testing::connection(app, "take"), *open.predicate), true);
  EXPECT_EQ(constant_outcome(testing::connection(app, "put"), *open.predicate), false);
  model::Connection maybe = testing::connection(app, "take");
  maybe.body = model::Body{
      stmt("(if 40 (call len msg) ((emit 41 (record verb \"cancel\" pos (call vec3 0.0 0.0 0.0)))) "
           "((emit 42 (record verb \"take\" pos (call vec3 0.0 0.0 0.0)))))")};
  EXPECT_EQ(constant_outcome(maybe, *picking.predicate), std::nullopt);
  // One path without `emit` delivers the message itself: not a constant.
  maybe.body = model::Body{
      stmt("(if 40 (call len msg) ((emit 41 (record verb \"take\" pos (call vec3 0.0 0.0 0.0)))) "
           "())")};
  EXPECT_EQ(constant_outcome(maybe, *open.predicate), std::nullopt);
  // A predicate that reads nothing of the value is that constant even then.
  std::string err;
  std::optional<model::BodyExpr> never = model::parse_body_expr("(not true)", &err);
  ASSERT_TRUE(never) << err;
  EXPECT_EQ(constant_outcome(maybe, *never), false);
}

TEST(OwnDelivery, TakesOwnDeliverySpacesTakes) {
  TemporalResult r = two_takes(own_events());
  EXPECT_EQ(r.outcome, Outcome::Proved) << r.unknown_reason;
  EXPECT_EQ(r.induction_k, 1);
}

TEST(OwnDelivery, PutAfterTakeIsProvedByTheEventTakeOpens) {
  TemporalResult r = put_after_take(own_events());
  EXPECT_EQ(r.outcome, Outcome::Proved) << r.unknown_reason;
  EXPECT_EQ(r.induction_k, 1);
}

TEST(OwnDelivery, WithoutItsFeedTheEventIsTheEnvironments) {
  // The same app with e_arm_picking fed from another port's deliveries (as PullObject.cmd's
  // own is): the environment may unset it between two takes.
  model::App app = own_events();
  for (model::Event& e : app.events)
    if (e.name == "e_arm_picking") e.source = "PullObject.cmd";
  testing::connection(app, "feed_PickAndPlace_cmd").sets = {"e_take_open"};
  model::Connection feed = testing::connection(app, "feed_PickAndPlace_cmd");
  feed.name = "feed_PullObject_cmd";
  feed.source = "PullObject.cmd";
  feed.sets = {"e_arm_picking"};
  app.connections.push_back(feed);
  EXPECT_EQ(two_takes(app).outcome, Outcome::Violated);
}

TEST(OwnDelivery, ATakeThatMayCancelLeavesItsHoldFree) {
  model::App app = own_events();
  testing::connection(app, "take").body = model::Body{
      stmt("(if 40 (== (call len msg) 1) ((emit 41 (record verb \"cancel\" pos (call vec3 0.0 "
           "0.0 0.0)))) ((emit 42 (record verb \"take\" pos (call vec3 0.0 0.0 0.0)))))")};
  TemporalResult r = two_takes(app);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  std::vector<const TraceStep*> takes;
  for (const TraceStep& s : r.trace)
    if (s.connection == "take" && s.delivered) takes.push_back(&s);
  ASSERT_EQ(takes.size(), 2u);
  EXPECT_FALSE(lists(takes[0]->set, "e_arm_picking"));  // the first take delivered "cancel"
  expect_only_deliveries_set(r);
}

TEST(OwnDelivery, APutThatDoesNotReadTheEventIsRefuted) {
  model::App app = own_events();
  testing::connection(app, "put").constraint =
      testing::parse("e_taken and e_arm_idle and not e_arm_picking");
  TemporalResult r = put_after_take(app);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  EXPECT_EQ(r.trace.back().connection, "put");
  expect_only_deliveries_set(r);
}

// A take whose verb is its message (a string port): the solver says which deliveries can set
// e_take_open, and the counterexample's messages make them do what the trace needs.
TEST(OwnDelivery, TheDataDecidesAndTheCounterexampleFollowsIt) {
  model::App app = own_events();
  for (model::Module& m : app.modules)
    for (model::Port& p : m.ports)
      if (p.name == "cmd") p.type = parse_type("{verb: string, n: int}");
  for (model::Module& m : app.modules)
    if (m.name == "LookAround")
      m.ports.push_back({"verb", model::Direction::Out, parse_type("string"), {}});
  model::Connection& take = testing::connection(app, "take");
  take.source = "LookAround.verb";
  take.body =
      model::Body{stmt("(accept 40 (!= msg \"put\"))"), stmt("(emit 41 (record verb msg n 0))")};
  testing::connection(app, "put").body = model::Body{stmt("(emit 44 (record verb \"put\" n 1))")};
  z3::context ctx;
  DataQuery data(app, ctx, 4, std::chrono::steady_clock::now() + std::chrono::seconds(60));
  const model::Event& open = app.events.back();
  DataQuery::PredicateRange range = data.predicate_range(take, *open.predicate);
  EXPECT_TRUE(range.can_true);
  EXPECT_TRUE(range.can_false);
  EXPECT_FALSE(range.can_fail);
  range = data.predicate_range(testing::connection(app, "put"), *open.predicate);
  EXPECT_FALSE(range.can_true);
  EXPECT_TRUE(range.can_false);
  // take may deliver "cancel" (no hold) or another verb (the hold): two takes within 1 s.
  TemporalResult r =
      check(app, property(model::TemporalProperty::Kind::Spacing, "take", "", 1s), &data);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_TRUE(r.replay_test) << r.not_replayable;
  EXPECT_FALSE(lists(r.trace[0].set, "e_arm_picking"));
  // The status feed's events come from status messages, the delivery's from take's deliveries
  // (never a `set`); take's first message is "cancel".
  std::vector<Value> inputs;
  for (const model::TestStep& s : r.replay_test->steps) {
    if (s.kind == model::TestStep::Kind::Input && s.port == "LookAround.verb")
      inputs.push_back(s.value);
    EXPECT_NE(s.event, "e_arm_picking");
    EXPECT_NE(s.event, "e_take_open");
  }
  ASSERT_FALSE(inputs.empty());
  EXPECT_EQ(inputs[0], Value("cancel"));
}

}  // namespace
}  // namespace arbc::verify::temporal
