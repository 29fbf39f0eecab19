// A feed's derived events are decided by one message of their source
// (verify/temporal/feed_outcomes.h): `e_pos = S.s : s.v > 0.0` and `e_neg = S.s : s.v < 0.0` are
// never both present, so `never go while e_pos` for `go when e_pos and e_neg` is proved; with
// `for 1s` on e_pos two messages leave both, and the counterexample sets them with messages of
// S.s, never with the test's own `set`.
#include "verify/temporal/feed_outcomes.h"

#include <gtest/gtest.h>

#include "core/body_text.h"
#include "verify/temporal/absence.h"
#include "verify/test_models.h"

namespace arbc::verify::temporal {
namespace {

using namespace std::chrono_literals;
using Outcome = TemporalResult::Outcome;

model::Event derived(const std::string& name, const std::string& predicate,
                     std::optional<Nanos> lifetime) {
  model::Event e;
  e.name = name;
  e.source = "S.s";
  e.lifetime = lifetime;
  std::string err;
  e.predicate = model::parse_body_expr(predicate, &err);
  if (!e.predicate) throw std::runtime_error("bad predicate in a test: " + err);
  return e;
}

model::App feed_app(std::optional<Nanos> pos_lifetime) {
  model::App app;
  app.name = "feedapp";
  auto module = [&](const std::string& name, const std::string& port, model::Direction d) {
    app.modules.push_back({name, "", {{port, d, parse_type("{v: float}"), {}}}, {}});
  };
  module("S", "s", model::Direction::Out);
  module("B", "b", model::Direction::Out);
  module("P", "p", model::Direction::In);
  app.events = {derived("e_pos", "(> (field v msg) 0.0)", pos_lifetime),
                derived("e_neg", "(< (field v msg) 0.0)", std::nullopt)};
  model::Connection go;
  go.name = "go";
  go.source = "B.b";
  go.destination = "P.p";
  go.constraint = testing::parse("e_pos and e_neg");
  go.body = model::Body{};
  model::Connection feed;
  feed.name = "feed_S_s";
  feed.source = "S.s";
  feed.destination = "P.p";
  feed.kind = model::ConnectionKind::Feed;
  feed.generated = true;
  feed.constraint = Constraint::constant(false);
  feed.sets = feed.unsets = {"e_pos", "e_neg"};
  app.connections = {go, feed};
  app.arbitrated_ports.push_back({"P.p", false, false, {"go"}, {}, {}});
  return app;
}

TemporalResult never_go_while_pos(const model::App& app, z3::context& ctx, DataQuery* data) {
  model::TemporalProperty p{
      model::TemporalProperty::Kind::Absence, "P.p", "go", 0s, {}, "e_pos", "", false, {}};
  std::string error;
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::optional<TemporalResult> r = check_absence(app, p, 6, ctx, data, deadline, &error);
  EXPECT_TRUE(r) << error;
  return r ? *r : TemporalResult{};
}

TEST(FeedOutcomes, OneMessageNeverMakesBothPresent) {
  model::App app = feed_app(std::nullopt);
  z3::context ctx;
  DataQuery data(app, ctx, 4, std::chrono::steady_clock::now() + std::chrono::seconds(60));
  std::string err;
  std::optional<PortShape> shape = port_shape(app, "P.p", &err, &data);
  ASSERT_TRUE(shape) << err;
  for (const Entry& e : shape->entries) EXPECT_TRUE(e.by_message) << e.event;
  EXPECT_FALSE(shape->excluded_outcomes.empty());  // both set by one message
  EXPECT_FALSE(shape->excluded_at_start.empty());  // nor both present in any state
  TemporalResult r = never_go_while_pos(app, ctx, &data);
  EXPECT_EQ(r.outcome, Outcome::Proved) << r.unknown_reason;
}

TEST(FeedOutcomes, WithoutTheDataTheFeedIsFree) {
  // No data query: nothing says the predicates exclude each other, and the model stays free
  // (the verdict then rests on the replay, which the CLI runs).
  model::App app = feed_app(std::nullopt);
  z3::context ctx;
  EXPECT_EQ(never_go_while_pos(app, ctx, nullptr).outcome, Outcome::Violated);
}

TEST(FeedOutcomes, ALastingEventIsSetByMessagesOnly) {
  model::App app = feed_app(Nanos(1s));
  z3::context ctx;
  DataQuery data(app, ctx, 4, std::chrono::steady_clock::now() + std::chrono::seconds(60));
  TemporalResult r = never_go_while_pos(app, ctx, &data);
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_TRUE(r.replay_test) << r.not_replayable;
  int messages = 0;
  for (const model::TestStep& s : r.replay_test->steps) {
    EXPECT_EQ(s.kind, model::TestStep::Kind::Input) << s.event;  // never `set`/`unset`
    if (s.port == "S.s") ++messages;
  }
  EXPECT_GE(messages, 2);  // one that sets e_pos, one that sets e_neg
}

// `e_pos = S.s : s.v > 0.0` and `e_rest = S.s : not (s.v > 0.0)`: every message of S.s sets
// exactly one, so "both absent" is a combination no message gives, but it is the state before
// S.s's first message. `go when not e_pos and not e_rest and e_b` delivers there once C.c has set
// e_b: `never go while e_b` is violated by two messages. Bounded to one, k-induction's any state
// must keep "both absent" (exclude()'s `start`), or the one-message step is unsat and the
// property is "proved" (the mutant feed-start-excludes-no-message of scripts/mutation_sites.txt).
model::App before_the_first_message_app() {
  model::App app = feed_app(std::nullopt);
  app.modules.push_back(
      {"C", "", {{"c", model::Direction::Out, parse_type("{v: float}"), {}}}, {}});
  app.events = {derived("e_pos", "(> (field v msg) 0.0)", std::nullopt),
                derived("e_rest", "(not (> (field v msg) 0.0))", std::nullopt),
                derived("e_b", "(> (field v msg) 0.0)", std::nullopt)};
  app.events[2].source = "C.c";
  app.connections[0].constraint = testing::parse("not e_pos and not e_rest and e_b");
  app.connections[1].sets = app.connections[1].unsets = {"e_pos", "e_rest"};
  model::Connection feed_c = app.connections[1];
  feed_c.name = "feed_C_c";
  feed_c.source = "C.c";
  feed_c.sets = feed_c.unsets = {"e_b"};
  app.connections.push_back(feed_c);
  return app;
}

TEST(FeedOutcomes, AnyStateKeepsTheStateBeforeTheFirstMessage) {
  model::App app = before_the_first_message_app();
  model::TemporalProperty p{
      model::TemporalProperty::Kind::Absence, "P.p", "go", 0s, {}, "e_b", "", false, {}};
  for (int bound : {1, 2}) {
    z3::context ctx;
    DataQuery data(app, ctx, 4, std::chrono::steady_clock::now() + std::chrono::seconds(60));
    std::string error;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    std::optional<TemporalResult> r = check_absence(app, p, bound, ctx, &data, deadline, &error);
    ASSERT_TRUE(r) << error;
    if (bound == 1)
      EXPECT_EQ(r->outcome, Outcome::HoldsToBound) << "bound 1: " << r->proof;
    else
      EXPECT_EQ(r->outcome, Outcome::Violated) << "bound 2";
  }
}

}  // namespace
}  // namespace arbc::verify::temporal
