// core/duration_literal.h: times written as the spec language writes durations.
#include "core/duration_literal.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

TEST(DurationLiteral, MillisecondsBelowASecondSecondsFromOne) {
  EXPECT_EQ(duration_literal(0), "0s");
  EXPECT_EQ(duration_literal(0.1), "100ms");
  EXPECT_EQ(duration_literal(0.12), "120ms");
  EXPECT_EQ(duration_literal(0.0005), "0.5ms");
  EXPECT_EQ(duration_literal(1), "1s");
  EXPECT_EQ(duration_literal(1.2), "1.2s");
  EXPECT_EQ(duration_literal(90), "90s");
}

TEST(DurationLiteral, RoundsToTheMicrosecond) {
  EXPECT_EQ(duration_literal(0.1 + 0.2), "300ms");  // binary noise of a simulated clock
  EXPECT_EQ(duration_literal(0.9999999), "1s");     // not 1000ms
  EXPECT_EQ(duration_literal(0.0000016), "0.002ms");
  EXPECT_EQ(duration_literal(-0.0000001), "0s");
  EXPECT_EQ(duration_literal(2.0000001), "2s");
}

// Instants and durations of a run are whole nanoseconds, written exactly (core/instant.h).
TEST(DurationLiteral, NanosecondsAreExact) {
  using std::chrono::milliseconds;
  EXPECT_EQ(duration_literal(Nanos(0)), "0s");
  EXPECT_EQ(duration_literal(milliseconds(100)), "100ms");
  EXPECT_EQ(duration_literal(Nanos(1)), "0.000001ms");
  EXPECT_EQ(duration_literal(Nanos(999'999'999)), "999.999999ms");
  EXPECT_EQ(duration_literal(Nanos(1'000'000'000)), "1s");
  EXPECT_EQ(duration_literal(Nanos(1'000'000'001)), "1.000000001s");
  EXPECT_EQ(duration_literal(milliseconds(1200)), "1.2s");
  EXPECT_EQ(duration_literal(milliseconds(-250)), "-250ms");
}

}  // namespace
}  // namespace arbc

namespace arbc {
namespace {

// A live view's age: milliseconds, rounded down (47.432752 ms is 47ms).
TEST(DurationLiteral, AgesToTheMillisecond) {
  using namespace std::chrono_literals;
  EXPECT_EQ(age_literal(47432752ns), "47ms");
  EXPECT_EQ(age_literal(11146968094ns), "11.146s");
  EXPECT_EQ(age_literal(999999ns), "0s");
}

}  // namespace
}  // namespace arbc
