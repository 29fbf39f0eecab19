// Event names that are prefixes of each other, or short enough to appear inside other words
// (`a` in `and`), must not interfere: YARP's substring substitution gets these wrong.
#include <gtest/gtest.h>

#include "core/compiled_constraint.h"
#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

const char* kNames[] = {"e", "e_ball", "e1", "e10", "a"};

TEST(PrefixNamesTest, CompiledConstraintsAgreeWithTheTreeInEveryState) {
  const char* constraints[] = {
      "e",
      "e_ball",
      "e1 and not e10",
      "a and e",
      "not e and e_ball",
      "e10 or (a and not e1)",
      "e and e_ball and e1 and e10 and a",
      "not a",
      "(e or e1) and not (e_ball or e10)",
  };
  for (const char* text : constraints) {
    std::string error;
    std::optional<Constraint> parsed = parse_constraint(text, &error);
    ASSERT_TRUE(parsed) << text << ": " << error;
    EventIndex index;
    for (const char* n : kNames) index.intern(n);
    CompiledConstraint c = CompiledConstraint::compile(*parsed, index);
    for (int state = 0; state < 32; ++state) {
      EventMask mask;
      std::set<std::string> present;
      for (int i = 0; i < 5; ++i) {
        if (state & (1 << i)) {
          mask.set(index.find(kNames[i]));
          present.insert(kNames[i]);
        }
      }
      EXPECT_EQ(c.evaluate(mask), evaluate(*parsed, present)) << text << " state " << state;
    }
  }
}

// The same through the runtime: only `e_ball` is set, so `e` must not be selected.
TEST(PrefixNamesTest, RuntimeSelectsByWholeNames) {
  testing::TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("setter", "Src.x", "Sink.x", "false",
            "PortMonitor.accept = function(m) PortMonitor.setEvent('e_ball') "
            "PortMonitor.setEvent('e10') return true end\n",
            model::ConnectionKind::Feed);
  t.connect("r_e", "Src.x", "Sink.x", "e");
  t.connect("r_e1", "Src.x", "Sink.x", "e1");
  t.connect("r_a", "Src.x", "Sink.x", "a");
  t.connect("r_ball", "Src.x", "Sink.x", "e_ball and e10 and not e and not e1 and not a");
  auto rt = t.start();
  testing::TestApp::publish_at(*rt, 1, "Src", "x", Value(1));
  rt->advance(2s);
  auto stats = rt->stats();
  EXPECT_EQ(testing::TestApp::stats_of(stats, "r_e").delivered, 0u);
  EXPECT_EQ(testing::TestApp::stats_of(stats, "r_e1").delivered, 0u);
  EXPECT_EQ(testing::TestApp::stats_of(stats, "r_a").delivered, 0u);
  EXPECT_EQ(testing::TestApp::stats_of(stats, "r_ball").delivered, 1u);
}

}  // namespace
}  // namespace arbc
