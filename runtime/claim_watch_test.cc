#include "runtime/claim_watch.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

Nanos sec(double seconds) { return nanos_from_seconds(seconds); }

// Source S.out feeds rule `r` into D.q, arbitrated; `given S.out every 500ms`; `exclusive { a, b
// }`.
model::App app() {
  model::App a;
  model::Connection rule;
  rule.kind = model::ConnectionKind::Rule;
  rule.name = "r";
  rule.source = "S.out";
  rule.destination = "D.q";
  rule.sets = {"a", "b"};  // its monitor's: the group's events are in D.q's container
  a.connections.push_back(rule);
  model::ArbitratedPort port;
  port.port = "D.q";
  port.rules = {"r"};
  a.arbitrated_ports.push_back(port);
  a.rates.push_back({"S.out", sec(0.5), {}});
  a.exclusive_groups.push_back({{"a", "b"}, {}});
  return a;
}

TraceRecord publish(double t) {
  TraceRecord r;
  r.kind = TraceKind::Publish;
  r.t = sec(t);
  r.port = "S.out";
  return r;
}

std::vector<std::string> broken(const ClaimWatch& w) {
  std::vector<std::string> out;
  for (const ClaimViolation& v : w.violations()) out.push_back(v.claim + ": " + v.what);
  return out;
}

TEST(ClaimWatchTest, AProcessThatMediatesNothingWatchesNothing) {
  model::App a = app();
  ClaimWatch world(a, {ModuleSet::none(), ModuleSet::everything()});
  EXPECT_TRUE(world.empty());  // not even the exclusive group: no decision is made here
  ClaimWatch mediator(a, {ModuleSet::everything(), ModuleSet::none()});
  EXPECT_EQ(mediator.size(), 2u);                                     // the rate and the group
  ClaimWatch other(a, {ModuleSet{false, {"E"}}, ModuleSet::none()});  // mediates another module
  EXPECT_TRUE(other.empty());
}

TEST(ClaimWatchTest, ARateCountsFromTheRunsStartAfterTheWaitForPeers) {
  model::App a = app();
  ClaimWatch w(a);
  w.start(sec(2.0));  // the transport waited two seconds for its peers
  w.observe(publish(2.4));
  w.observe(publish(2.9));
  w.finish(sec(3.2));
  EXPECT_TRUE(w.violations().empty()) << broken(w)[0];
  ClaimWatch late(a);
  late.start(sec(2.0));
  late.observe(publish(2.6));  // its first message 0.6 s after the start
  EXPECT_EQ(broken(late), std::vector<std::string>{"given S.out every 500ms: nothing from S.out "
                                                   "between 2s and 2.6s"});
}

TEST(ClaimWatchTest, ASourceInAnotherProcessStartsWhenItFirstSpeaks) {
  model::App a = app();
  ClaimWatch w(a, {ModuleSet::everything(), ModuleSet::none()});
  w.start(sec(0));
  w.observe(publish(3.0));  // a program started three seconds after the mediator
  w.observe(publish(3.5));
  w.observe(publish(4.1));  // a gap of 0.6 s once it runs
  EXPECT_EQ(broken(w), std::vector<std::string>{"given S.out every 500ms: nothing from S.out "
                                                "between 3.5s and 4.1s"});
  EXPECT_EQ(w.violations()[0].t, sec(4.0));  // at the deadline it missed
  // One that never speaks is said at the end.
  ClaimWatch silent(a, {ModuleSet::everything(), ModuleSet::none()});
  silent.start(sec(1));
  silent.finish(sec(10));
  EXPECT_EQ(broken(silent),
            std::vector<std::string>{"given S.out every 500ms: nothing from S.out from the start "
                                     "(1s) to the end of the run (10s): it never published"});
  // A source hosted here is owed from the start.
  ClaimWatch hosted(a);
  hosted.start(sec(1));
  hosted.observe(publish(3.0));
  EXPECT_EQ(hosted.violations().size(), 1u);
}

// Port D.q: `a` and `b` from S.out (one message reaches both), `c` from T.out; a `when e`,
// b `when not e`, c `when not e`; `assert D.q: a -> f`.
model::App two_sources() {
  model::App app;
  auto rule = [&](const std::string& name, const std::string& source, Constraint when) {
    model::Connection c;
    c.kind = model::ConnectionKind::Rule;
    c.name = name, c.source = source, c.destination = "D.q";
    c.constraint = std::move(when);
    app.connections.push_back(c);
  };
  rule("a", "S.out", Constraint::event_ref("e"));
  rule("b", "S.out", Constraint::negate(Constraint::event_ref("e")));
  rule("c", "T.out", Constraint::negate(Constraint::event_ref("e")));
  model::ArbitratedPort port;
  port.port = "D.q";
  port.rules = {"a", "b", "c"};
  model::Assertion assertion;
  assertion.rule = "a";
  assertion.property = Constraint::event_ref("f");
  port.asserts.push_back(assertion);
  app.arbitrated_ports.push_back(port);
  return app;
}

TraceRecord decided(double t, const std::string& rule, bool delivered) {
  TraceRecord r;
  r.kind = delivered ? TraceKind::Deliver : TraceKind::Drop;
  r.reason = DropReason::NotSelected;
  r.t = sec(t);
  r.connection = rule;
  r.port = "D.q";
  return r;
}

TraceRecord set_event(double t, const std::string& name) {
  TraceRecord r;
  r.kind = TraceKind::Event;
  r.t = sec(t);
  r.op = "set";
  r.event = name;
  r.owner = "feed";
  r.port = "D.q";
  return r;
}

TEST(ClaimWatchTest, OneMessageDeliveredByTwoRulesBreaksTheirPortsExclusivity) {
  model::App a = two_sources();
  ClaimWatch w(a);
  EXPECT_EQ(w.size(), 2u);       // D.q's exclusivity and the assert
  w.observe(set_event(0, "e"));  // c, of the other source, is not selected: only messages count
  w.observe(set_event(0, "f"));
  // Message 1 of S.out: a delivers, b drops; message 2: b delivers, a drops; then message 3
  // delivered by both (b decides it before a has seen message 3: the order of connections).
  w.observe(decided(0.1, "a", true));
  w.observe(decided(0.1, "b", false));
  w.observe(decided(0.2, "b", true));
  w.observe(decided(0.2, "a", false));
  EXPECT_TRUE(w.violations().empty()) << broken(w)[0];
  w.observe(decided(0.3, "b", true));
  w.observe(decided(0.3, "a", true));
  EXPECT_EQ(broken(w), std::vector<std::string>{
                           "D.q: rules a, b, c are never selected together: one message from "
                           "S.out delivered by both 'b' and 'a' at 300ms"});
}

TEST(ClaimWatchTest, ARuleDeliveringWhereARuleOfAnotherSourceIsSelectedBreaksIt) {
  model::App a = two_sources();
  ClaimWatch w(a);
  w.observe(decided(0.1, "b", true));  // no event: b and c are both selected (not e)
  EXPECT_EQ(broken(w), std::vector<std::string>{
                           "D.q: rules a, b, c are never selected together: 'b' delivered at "
                           "100ms in a state where 'c' is selected too (events present: none)"});
  // Where events may start unknown (a restarted mediator), only the same-message check runs.
  ClaimWatch restarted(a, {.states_known = false});
  restarted.observe(decided(0.1, "b", true));
  EXPECT_TRUE(restarted.violations().empty());
}

// `then set` (docs/language.md#events-set-on-delivery): b, of S.out, sets g as it delivers and
// c, of T.out, now reads `not g`: in the state b delivered in c is selected, in the state it
// left it is not, so b's delivery keeps c out and nothing is broken. Without the effect, the
// same delivery breaks the claim.
TEST(ClaimWatchTest, ADeliveryThatKeepsTheOtherRuleOutIsJudgedInTheStateItLeaves) {
  model::App a = two_sources();
  for (model::Connection& c : a.connections) {
    if (c.name == "b") c.delivery_sets = {"g"}, c.sets = {"g"};
    if (c.name == "c")
      c.constraint = Constraint::conjunction({Constraint::negate(Constraint::event_ref("e")),
                                              Constraint::negate(Constraint::event_ref("g"))});
  }
  ClaimWatch w(a);
  w.observe(decided(0.1, "b", true));
  EXPECT_TRUE(w.violations().empty()) << broken(w)[0];
  for (model::Connection& c : a.connections)
    if (c.name == "b") c.delivery_sets.clear();
  ClaimWatch without(a);
  without.observe(decided(0.1, "b", true));
  EXPECT_EQ(broken(without).size(), 1u);
}

TEST(ClaimWatchTest, AnAssertIsJudgedInThePortsStateAtEachDeliveryOfItsRule) {
  model::App a = two_sources();
  ClaimWatch w(a);
  w.observe(set_event(0, "e"));
  w.observe(set_event(0, "f"));
  w.observe(decided(0.1, "a", true));
  EXPECT_TRUE(w.violations().empty()) << broken(w)[0];
  model::App no_f = two_sources();
  ClaimWatch v(no_f);
  v.observe(set_event(0, "e"));
  v.observe(decided(0.1, "a", true));
  EXPECT_EQ(broken(v), std::vector<std::string>{
                           "assert D.q: a -> f: 'a' delivered at 100ms with f false in D.q "
                           "(events present: e)"});
}

TEST(ClaimWatchTest, InATestARateIsJudgedBetweenASourcesFirstAndLastMessages) {
  model::App a = app();
  ClaimWatch w(a, {.test = true});
  w.start(sec(0));
  w.observe(publish(2.0));  // silent before: the test starts the source when it says
  w.observe(publish(2.5));
  w.observe(publish(9.0));  // other sources' records in between would not break it either
  w.finish(sec(20));        // nor the silence after its last message
  EXPECT_EQ(broken(w), std::vector<std::string>{"given S.out every 500ms: nothing from S.out "
                                                "between 2.5s and 9s"});
  ClaimWatch quiet(a, {.test = true});
  quiet.finish(sec(20));
  EXPECT_TRUE(quiet.violations().empty());
}

// `assume g only after a;` speaks of what the environment reports: a feed's report of g before
// any delivery of `a` breaks it even if no rule decides while g is present (the proof rules the
// report out, so a response to g owed from it would be reported as a broken claim instead: drt
// seed 12001 spec 118). A report after a delivery of `a` keeps it.
TEST(ClaimWatchTest, AnAssumedEventReportedBeforeItsRuleDeliveredBreaksTheAssumption) {
  model::App a = two_sources();
  model::Assumption assumed;
  assumed.event = "g";
  assumed.port = "D.q";
  assumed.after = "a";
  a.assumptions.push_back(assumed);
  ClaimWatch w(a);
  w.observe(set_event(0.1, "g"));
  EXPECT_EQ(broken(w), std::vector<std::string>{
                           "assume g only after a: g present in D.q at 100ms (reported by feed) "
                           "with no delivery of 'a'"});
  ClaimWatch kept(a);
  kept.observe(set_event(0, "e"));
  kept.observe(set_event(0, "f"));
  kept.observe(decided(0.1, "a", true));
  kept.observe(decided(0.1, "b", false));
  kept.observe(set_event(0.2, "g"));
  EXPECT_TRUE(kept.violations().empty()) << broken(kept)[0];
}

// An invariant is judged in a port fed some of its events, the others free as the port's proof
// reads them (D.q's container never holds x: `a or x` may hold by x, `a and not b` may not); one
// over events fed into no port is watched nowhere, and said to be, not counted kept.
TEST(ClaimWatchTest, AnInvariantIsJudgedWhereItsEventsAreFed) {
  model::App a = app();
  auto ref = [](const char* e) { return Constraint::event_ref(e); };
  a.invariants.push_back({Constraint::disjunction({ref("a"), ref("x")}), {}});
  a.invariants.push_back({Constraint::conjunction({ref("a"), Constraint::negate(ref("b"))}), {}});
  a.invariants.push_back({Constraint::negate(Constraint::conjunction({ref("x"), ref("y")})), {}});
  ClaimWatch w(a);
  TraceRecord r = publish(0.1);
  r.kind = TraceKind::Deliver, r.connection = "r", r.port = "D.q";
  w.observe(r);  // no event present
  EXPECT_EQ(broken(w), std::vector<std::string>{"invariant a and not b: false in D.q at 100ms "
                                                "(events present: none)"});
  EXPECT_EQ(w.size(), 4u);  // the rate, the group, the first two invariants
  EXPECT_EQ(w.unwatched(), std::vector<std::string>{
                               "assumption invariant not (x and y): no port is fed x, y (no rule "
                               "or assert reads them), so no proof rests on it and no run can see "
                               "it broken"});
  ClaimWatch world(a, {ModuleSet::none(), ModuleSet::everything()});
  EXPECT_TRUE(world.empty());  // decides nothing here: says nothing
}

}  // namespace
}  // namespace arbc
