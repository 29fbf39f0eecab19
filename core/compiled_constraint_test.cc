#include "core/compiled_constraint.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace arbc {
namespace {

// Compiled evaluation must agree with the reference tree walk on every event state.
void expect_agrees_everywhere(const std::string& text) {
  ConstraintParse p = parse_constraint(text);
  ASSERT_TRUE(p.ok) << p.error;
  EventIndex index;
  CompiledConstraint compiled = CompiledConstraint::compile(p.constraint, index);
  int n = index.size();
  ASSERT_LE(n, 12);
  for (int state = 0; state < (1 << n); ++state) {
    EventMask mask;
    std::set<std::string> present;
    for (int i = 0; i < n; ++i) {
      if (state & (1 << i)) {
        mask.set(i);
        present.insert(index.name(i));
      }
    }
    EXPECT_EQ(compiled.evaluate(mask), evaluate(p.constraint, present))
        << text << " in state " << state;
  }
}

TEST(CompiledConstraintTest, CubesAndProgramsAgreeWithTheTree) {
  expect_agrees_everywhere("true");
  expect_agrees_everywhere("false");
  expect_agrees_everywhere("not e_taken and e_arm_idle and e_pull_idle");
  expect_agrees_everywhere("a and not a");
  expect_agrees_everywhere("(a or b) and not (c and d) or e");
  expect_agrees_everywhere("e or e_ball and not e1 or e10 and a");
}

TEST(CompiledConstraintTest, EventsBeyondSixtyFourBits) {
  EventIndex index;
  for (int i = 0; i < 100; ++i) index.intern("pad" + std::to_string(i));
  CompiledConstraint c =
      CompiledConstraint::compile(parse_constraint("pad99 and not pad3").constraint, index);
  EventMask mask;
  EXPECT_FALSE(c.evaluate(mask));
  mask.set(99);
  EXPECT_TRUE(c.evaluate(mask));
  mask.set(3);
  EXPECT_FALSE(c.evaluate(mask));
}

// The first word is held inline and the rest in a vector: set, reset, test and clear agree
// with a plain set of ids across the boundary, and a one-word cube ignores higher words.
TEST(CompiledConstraintTest, MaskWordsAgreeWithASetOfIds) {
  EventMask mask;
  std::set<int> ids;
  std::mt19937 random(7);
  for (int step = 0; step < 2000; ++step) {
    int id = static_cast<int>(random() % 200);
    if (step % 500 == 499) {
      mask.clear();
      ids.clear();
    } else if (random() % 3 == 0) {
      mask.reset(id);
      ids.erase(id);
    } else {
      mask.set(id);
      ids.insert(id);
    }
    for (int probe : {0, 1, 62, 63, 64, 65, 127, 128, 199, 250, id})
      ASSERT_EQ(mask.test(probe), ids.count(probe) == 1) << "step " << step << " id " << probe;
  }
  EventIndex index;
  for (int i = 0; i < 70; ++i) index.intern("e" + std::to_string(i));
  CompiledConstraint low =
      CompiledConstraint::compile(parse_constraint("e1 and not e2").constraint, index);
  EventMask state;
  state.set(1);
  state.set(66);
  EXPECT_TRUE(low.evaluate(state));
  state.set(2);
  EXPECT_FALSE(low.evaluate(state));
  state.reset(2);
  state.reset(1);
  EXPECT_FALSE(low.evaluate(state));
}

TEST(CompiledConstraintTest, DeepProgramsUseTheHeapStack) {
  std::string text = "a";
  for (int i = 0; i < 150; ++i) text = "(" + text + " or b" + std::to_string(i % 3) + ") and c";
  ConstraintParse p = parse_constraint(text);
  ASSERT_TRUE(p.ok);
  EventIndex index;
  CompiledConstraint c = CompiledConstraint::compile(p.constraint, index);
  EventMask mask;
  mask.set(index.find("a"));
  mask.set(index.find("c"));
  EXPECT_TRUE(c.evaluate(mask));
  mask.reset(index.find("c"));
  EXPECT_FALSE(c.evaluate(mask));
}

// as_cube: the one cube decomposition (compiled constraints and verify's shortcut).
TEST(CompiledConstraintTest, AsCubeSplitsConjunctionsOfLiterals) {
  EventIndex index;
  std::optional<Cube> cube = as_cube(parse_constraint("a and not b and c").constraint, index);
  ASSERT_TRUE(cube.has_value());
  EXPECT_EQ(cube->required, (std::vector<uint64_t>{0b101}));   // a = 0, c = 2
  EXPECT_EQ(cube->forbidden, (std::vector<uint64_t>{0b010}));  // b = 1
  EXPECT_FALSE(cube->contradictory());

  std::optional<Cube> always = as_cube(parse_constraint("true").constraint, index);
  ASSERT_TRUE(always.has_value());
  EXPECT_TRUE(always->required.empty());

  EXPECT_TRUE(as_cube(parse_constraint("a and not a").constraint, index)->contradictory());
  EXPECT_FALSE(as_cube(parse_constraint("a or b").constraint, index).has_value());
  EXPECT_FALSE(as_cube(parse_constraint("a and (b or c)").constraint, index).has_value());
  EXPECT_FALSE(as_cube(parse_constraint("false").constraint, index).has_value());
}

TEST(CompiledConstraintTest, AsCubeSpansWordsBeyondSixtyFourEvents) {
  EventIndex index;
  for (int i = 0; i < 70; ++i) index.intern("e" + std::to_string(i));
  std::optional<Cube> cube = as_cube(parse_constraint("e1 and not e69").constraint, index);
  ASSERT_TRUE(cube.has_value());
  EXPECT_EQ(cube->required, (std::vector<uint64_t>{0b10, 0}));
  EXPECT_EQ(cube->forbidden, (std::vector<uint64_t>{0, uint64_t{1} << 5}));
}

}  // namespace
}  // namespace arbc
