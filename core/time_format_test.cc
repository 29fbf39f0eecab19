#include "core/time_format.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

// The plot is 790 px wide (TimelineLayout): a pixel is end / 790.
TimeFormat of_run(double end) { return TimeFormat(end, end / 790); }

TEST(TimeFormat, ARunOfSecondsKeepsMilliseconds) {
  TimeFormat f = of_run(44.9);
  EXPECT_EQ(f.text(12.3), "12.300 s");
  EXPECT_EQ(f.span(0.15, 0.3), "0.150\u20130.300 s");
}

TEST(TimeFormat, ShortRunsAreInMillisecondsOrMicroseconds) {
  EXPECT_EQ(of_run(0.005).text(0.00125), "1.250 ms");
  EXPECT_EQ(of_run(0.5).text(0.25), "250.0 ms");
  EXPECT_EQ(of_run(0.0005).text(0.00012), "120.0 \u00b5s");
}

// Instants a pixel apart are written differently: the hover of a bar tells them apart.
TEST(TimeFormat, APixelApartIsWrittenApart) {
  for (double end : {0.002, 0.05, 0.9, 3.0, 60.0, 7200.0}) {
    TimeFormat f = of_run(end);
    double pixel = end / 790;
    for (double t : {0.0, end / 3, end / 2})
      EXPECT_NE(f.text(t), f.text(t + pixel)) << end << " " << t;
  }
}

// A span shorter than the resolution (a flag present for 0.3 ms of a minute's run) gets the
// decimals that tell its ends apart, up to nanoseconds.
TEST(TimeFormat, ASpanShorterThanThePrecisionGetsMoreDecimals) {
  TimeFormat f = of_run(60);
  EXPECT_EQ(f.span(12.3451, 12.3454), "12.3451\u201312.3454 s");
  EXPECT_EQ(f.span(1, 1 + 2e-9), "1.000000000\u20131.000000002 s");
  EXPECT_EQ(f.span(1, 1 + 1e-12), "1.000000000\u20131.000000000 s");  // no further
  EXPECT_EQ(f.span(2, 2), "2.000\u20132.000 s");
}

// Text without a plot: the unit of the run, and a thousandth of it told apart.
TEST(TimeFormat, ForARunWithoutAPlot) {
  EXPECT_EQ(TimeFormat::for_run(44.9).text(12.3), "12.300 s");
  EXPECT_EQ(TimeFormat::for_run(100000).text(23.4567), "23.457 s");
  EXPECT_EQ(TimeFormat::for_run(0.5).text(0.5), "500.0 ms");
  EXPECT_EQ(TimeFormat::for_run(0.002).text(0.00125), "1.250 ms");
  EXPECT_EQ(TimeFormat::for_run(0.0005).text(0.00012), "120.0 \u00b5s");
  EXPECT_EQ(TimeFormat::for_run(0).text(0), "0.000 s");
}

}  // namespace
}  // namespace arbc
