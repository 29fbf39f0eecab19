#include "runtime/claim_watch.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

Nanos ns(double seconds) { return nanos_from_seconds(seconds); }

// Source S.out feeds rule `r` into D.q, arbitrated; `given S.out every 500ms`; `exclusive { a, b
// }`.
model::App app() {
  model::App a;
  model::Connection rule;
  rule.kind = model::ConnectionKind::Rule;
  rule.name = "r";
  rule.source = "S.out";
  rule.destination = "D.q";
  a.connections.push_back(rule);
  model::ArbitratedPort port;
  port.port = "D.q";
  port.rules = {"r"};
  a.arbitrated_ports.push_back(port);
  a.rates.push_back({"S.out", ns(0.5), {}});
  a.exclusive_groups.push_back({{"a", "b"}, {}});
  return a;
}

TraceRecord publish(double t) {
  TraceRecord r;
  r.kind = TraceKind::Publish;
  r.t = ns(t);
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
  ClaimWatch world(a, ModuleSet::none(), ModuleSet::everything());
  EXPECT_TRUE(world.empty());  // not even the exclusive group: no decision is made here
  ClaimWatch mediator(a, ModuleSet::everything(), ModuleSet::none());
  EXPECT_EQ(mediator.size(), 2u);                                   // the rate and the group
  ClaimWatch other(a, ModuleSet{false, {"E"}}, ModuleSet::none());  // mediates another module
  EXPECT_TRUE(other.empty());
}

TEST(ClaimWatchTest, ARateCountsFromTheRunsStartAfterTheWaitForPeers) {
  model::App a = app();
  ClaimWatch w(a);
  w.start(ns(2.0));  // the transport waited two seconds for its peers
  w.observe(publish(2.4));
  w.observe(publish(2.9));
  w.finish(ns(3.2));
  EXPECT_TRUE(w.violations().empty()) << broken(w)[0];
  ClaimWatch late(a);
  late.start(ns(2.0));
  late.observe(publish(2.6));  // its first message 0.6 s after the start
  EXPECT_EQ(broken(late), std::vector<std::string>{"given S.out every 500ms: nothing from S.out "
                                                   "between 2s and 2.6s"});
}

TEST(ClaimWatchTest, ASourceInAnotherProcessStartsWhenItFirstSpeaks) {
  model::App a = app();
  ClaimWatch w(a, ModuleSet::everything(), ModuleSet::none());
  w.start(ns(0));
  w.observe(publish(3.0));  // a program started three seconds after the mediator
  w.observe(publish(3.5));
  w.observe(publish(4.1));  // a gap of 0.6 s once it runs
  EXPECT_EQ(broken(w), std::vector<std::string>{"given S.out every 500ms: nothing from S.out "
                                                "between 3.5s and 4.1s"});
  EXPECT_EQ(w.violations()[0].t, ns(4.0));  // at the deadline it missed
  // One that never speaks is said at the end.
  ClaimWatch silent(a, ModuleSet::everything(), ModuleSet::none());
  silent.start(ns(1));
  silent.finish(ns(10));
  EXPECT_EQ(broken(silent),
            std::vector<std::string>{"given S.out every 500ms: nothing from S.out from the start "
                                     "(1s) to the end of the run (10s): it never published"});
  // A source hosted here is owed from the start.
  ClaimWatch hosted(a);
  hosted.start(ns(1));
  hosted.observe(publish(3.0));
  EXPECT_EQ(hosted.violations().size(), 1u);
}

}  // namespace
}  // namespace arbc
