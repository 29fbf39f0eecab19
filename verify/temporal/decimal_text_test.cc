#include "verify/temporal/decimal_text.h"

#include <gtest/gtest.h>
#include <z3++.h>

#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {
namespace {

TEST(ShortestDecimal, NeverWritesAnExponent) {
  EXPECT_EQ(shortest_decimal(0.2), "0.2");
  EXPECT_EQ(shortest_decimal(1.0), "1");
  EXPECT_EQ(shortest_decimal(1.5), "1.5");
  EXPECT_EQ(shortest_decimal(250.0), "250");
  EXPECT_EQ(shortest_decimal(-0.25), "-0.25");
  EXPECT_EQ(shortest_decimal(0.0), "0");
  EXPECT_EQ(shortest_decimal(5e-5), "0.00005");
  EXPECT_EQ(shortest_decimal(5e-10), "0.0000000005");
  EXPECT_EQ(shortest_decimal(1e15), "1000000000000000");
  EXPECT_EQ(shortest_decimal(0.1 + 0.2), "0.30000000000000004");
}

// Z3 4.8 reads "5e-05" as (/ 1.0 0.0): a hold of 0.05ms was an unknown real in the proof, and
// one of 0.0000000005s crashed Z3 (SIGFPE). Every duration is the exact decimal the spec wrote.
TEST(Seconds, SmallAndLargeDurationsAreTheirExactValues) {
  z3::context ctx;
  z3::solver s(ctx);
  s.add(seconds(ctx, 5e-5) * 20000 != ctx.real_val(1));
  EXPECT_EQ(s.check(), z3::unsat);
  z3::solver t(ctx);
  t.add(seconds(ctx, 5e-10) * 2000000000 != ctx.real_val(1));
  EXPECT_EQ(t.check(), z3::unsat);
  z3::solver u(ctx);
  u.add(seconds(ctx, 1e15) != ctx.real_val("1000000000000000"));
  EXPECT_EQ(u.check(), z3::unsat);
  z3::solver w(ctx);
  w.add(seconds(ctx, 0.2) * 5 != ctx.real_val(1));
  EXPECT_EQ(w.check(), z3::unsat);
}

}  // namespace
}  // namespace arbc::verify::temporal
