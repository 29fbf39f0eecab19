#include "core/decimal_text.h"

#include <gtest/gtest.h>

namespace arbc {
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

}  // namespace
}  // namespace arbc
