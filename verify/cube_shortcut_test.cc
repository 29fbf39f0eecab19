#include "verify/cube_shortcut.h"

#include <gtest/gtest.h>

#include "verify/test_models.h"

namespace arbc::verify {
namespace {

// One port M.p with rules r0.. whose constraints are given, and a feed setting every event.
PortScope scope_of(model::App& app, const std::vector<std::string>& guards) {
  model::ArbitratedPort port{"M.p", false, false, {}, {}, {}};
  for (size_t i = 0; i < guards.size(); ++i) {
    model::Connection c;
    c.name = "r" + std::to_string(i);
    c.source = "S.o" + std::to_string(i);
    c.destination = "M.p";
    c.constraint = testing::parse(guards[i]);
    app.connections.push_back(c);
    port.rules.push_back(c.name);
  }
  app.arbitrated_ports.push_back(port);
  std::string error;
  std::optional<PortScope> scope = build_port_scope(app, app.arbitrated_ports.back(), &error);
  EXPECT_TRUE(scope) << error;
  return scope ? std::move(*scope) : PortScope{};
}

TEST(CubeShortcut, SettlesCubesAndLeavesTheRestToTheSolver) {
  model::App app;
  PortScope scope = scope_of(app, {"a and not b", "b and c", "a and c", "a or b", "a and not a"});
  CubeShortcut s(scope);
  EXPECT_EQ(s.can_hold(0), Known::Yes);
  EXPECT_EQ(s.can_hold(3), Known::Unknown);         // not a cube
  EXPECT_EQ(s.can_hold(4), Known::No);              // contradictory
  EXPECT_EQ(s.can_hold_together(0, 1), Known::No);  // not b / b
  EXPECT_EQ(s.can_hold_together(0, 2), Known::Yes);
  EXPECT_EQ(s.can_hold_together(0, 3), Known::Unknown);
  EXPECT_EQ(s.can_hold_together(2, 4), Known::No);
}

TEST(CubeShortcut, AWitnessMustSatisfyTheDomain) {
  model::App app;
  app.invariants.push_back({testing::parse("not a or d"), {}});  // a implies d
  PortScope scope = scope_of(app, {"a", "b"});
  CubeShortcut s(scope);
  EXPECT_EQ(s.can_hold(0), Known::Unknown);  // {a} breaks the invariant; {a, d} is for Z3
  EXPECT_EQ(s.can_hold(1), Known::Yes);
  EXPECT_EQ(s.can_hold_together(0, 1), Known::Unknown);
}

TEST(CubeShortcut, PairwiseDisjointOnlyWhenEveryPairClashes) {
  model::App priority;  // what `by priority` lowers to
  EXPECT_TRUE(CubeShortcut(scope_of(priority, {"a", "not a and b", "not a and not b"}))
                  .pairwise_disjoint());
  model::App overlap;  // r0 and r2 hold together in {a, c}
  EXPECT_FALSE(CubeShortcut(scope_of(overlap, {"a and not b", "b", "c"})).pairwise_disjoint());
  model::App not_cube;  // disjoint in fact, but only the solver can say so
  EXPECT_FALSE(CubeShortcut(scope_of(not_cube, {"a", "not a and (b or c)"})).pairwise_disjoint());
  model::App one;
  EXPECT_TRUE(CubeShortcut(scope_of(one, {"a or b"})).pairwise_disjoint());
}

}  // namespace
}  // namespace arbc::verify
