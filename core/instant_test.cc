#include "core/instant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace arbc {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;

TEST(Instant, DoublesRoundToTheNearestNanosecond) {
  EXPECT_EQ(nanos_from_seconds(0.3), milliseconds(300));
  EXPECT_EQ(nanos_from_seconds(0.1 + 0.2), milliseconds(300));        // 0.30000000000000004
  EXPECT_EQ(nanos_from_seconds(0.9999999995), Nanos(1'000'000'000));  // a half rounds away
  EXPECT_EQ(nanos_from_seconds(0.9999999994), Nanos(999'999'999));
  EXPECT_EQ(nanos_from_seconds(-0.25), milliseconds(-250));
  EXPECT_EQ(nanos_from_seconds(std::nan("")), Nanos(0));
  EXPECT_EQ(nanos_from_seconds(1e300), kNever);
  EXPECT_EQ(nanos_from_seconds(std::numeric_limits<double>::infinity()), kNever);
  EXPECT_EQ(nanos_from_seconds(-1e300), -kNever);
}

TEST(Instant, SecondsAreTheDoubleNearestTheDecimal) {
  EXPECT_EQ(seconds_of(milliseconds(300)), 0.3);
  EXPECT_EQ(seconds_of(Nanos(1)), 1e-9);
  EXPECT_EQ(seconds_of(seconds(2)), 2.0);
}

TEST(Instant, DecimalSecondsAreExact) {
  EXPECT_EQ(decimal_seconds(Nanos(0)), "0");
  EXPECT_EQ(decimal_seconds(milliseconds(300)), "0.3");
  EXPECT_EQ(decimal_seconds(seconds(2)), "2");
  EXPECT_EQ(decimal_seconds(Nanos(1'000'000'001)), "1.000000001");
  EXPECT_EQ(decimal_seconds(Nanos(999'999'999)), "0.999999999");
  EXPECT_EQ(decimal_seconds(milliseconds(-250)), "-0.25");
  EXPECT_EQ(decimal_seconds(kNever), "9223372036.854775807");
  EXPECT_EQ(decimal_seconds(Nanos::min()), "-9223372036.854775808");
}

TEST(Instant, DecimalTextIsReadExactly) {
  constexpr int64_t s = 1'000'000'000, ms = 1'000'000, min = 60'000'000'000;
  EXPECT_EQ(nanos_of_decimal("1.5", s), milliseconds(1500));
  EXPECT_EQ(nanos_of_decimal("0.000000001", s), Nanos(1));
  EXPECT_EQ(nanos_of_decimal("1.000000001000", s), Nanos(1'000'000'001));  // trailing zeros
  EXPECT_EQ(nanos_of_decimal("0.000001", ms), Nanos(1));
  EXPECT_EQ(nanos_of_decimal("0.5", min), seconds(30));
  EXPECT_EQ(nanos_of_decimal("0.0000000001", min), Nanos(6));  // 10 digits, but of a minute
  EXPECT_EQ(nanos_of_decimal("007", s), seconds(7));
  // Ten digits of a second is not a whole number of nanoseconds, however close.
  EXPECT_EQ(nanos_of_decimal("0.9999999995", s), std::nullopt);
  EXPECT_EQ(nanos_of_decimal("1.0000000001", s), std::nullopt);
  EXPECT_EQ(nanos_of_decimal("0.0000001", ms), std::nullopt);
  EXPECT_EQ(nanos_of_decimal("0.30000000000000000001", s), std::nullopt);  // no double rounding
  // Beyond about 100 years, and text that is not a plain decimal.
  EXPECT_EQ(nanos_of_decimal("3155760000", s), kLongestDuration);
  EXPECT_EQ(nanos_of_decimal("3155760000.000000001", s), std::nullopt);
  EXPECT_EQ(nanos_of_decimal("99999999999999999999999", s), std::nullopt);
  EXPECT_EQ(nanos_of_decimal("", s), std::nullopt);
  EXPECT_EQ(nanos_of_decimal(".5", s), std::nullopt);
  EXPECT_EQ(nanos_of_decimal("1e3", s), std::nullopt);
  EXPECT_EQ(nanos_of_decimal("-1", s), std::nullopt);
}

TEST(Instant, ADoubleIsWholeNanosecondsWhenItsShortestDecimalIs) {
  EXPECT_EQ(whole_nanos(0.1), milliseconds(100));
  EXPECT_EQ(whole_nanos(1e-9), Nanos(1));
  EXPECT_EQ(whole_nanos(1.000000001), Nanos(1'000'000'001));
  EXPECT_EQ(whole_nanos(3e9), seconds(3'000'000'000));
  EXPECT_EQ(whole_nanos(0.0), Nanos(0));
  EXPECT_EQ(whole_nanos(0.9999999995), std::nullopt);
  EXPECT_EQ(whole_nanos(1.0 / 3), std::nullopt);
  EXPECT_EQ(whole_nanos(0.1 + 0.2), std::nullopt);
  EXPECT_EQ(whole_nanos(5e-10), std::nullopt);
  EXPECT_EQ(whole_nanos(-1), std::nullopt);
  EXPECT_EQ(whole_nanos(1e300), std::nullopt);
  EXPECT_EQ(whole_nanos(std::nan("")), std::nullopt);
}

TEST(Instant, LaterSaturatesAtNever) {
  EXPECT_EQ(later(seconds(1), seconds(2)), seconds(3));
  EXPECT_EQ(later(seconds(1), kNever), kNever);
  EXPECT_EQ(later(kNever, Nanos(0)), kNever);
  EXPECT_EQ(later(kLongestDuration, kLongestDuration), 2 * kLongestDuration);
}

}  // namespace
}  // namespace arbc
