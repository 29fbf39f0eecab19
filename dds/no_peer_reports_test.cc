// The times at which a DDS run says again that a topic has no peer.
#include "dds/no_peer_reports.h"

#include <gtest/gtest.h>

namespace arbc::dds {
namespace {

TEST(NoPeerReportsTest, GrowThenEveryFiveMinutes) {
  std::string said;
  for (int k = 0; k < 8; ++k) said += wall_span_text(no_peer_report_at(k, 10)) + ", ";
  EXPECT_EQ(said, "10 s, 30 s, 1 min, 2 min, 5 min, 10 min, 15 min, 20 min, ");
}

// A shorter first report (the tests') keeps the proportions.
TEST(NoPeerReportsTest, ScaleWithTheFirst) {
  EXPECT_EQ(no_peer_report_at(0, 0.5), 0.5);
  EXPECT_EQ(no_peer_report_at(1, 0.5), 1.5);
  EXPECT_EQ(no_peer_report_at(2, 0.5), 3);
  EXPECT_EQ(wall_span_text(90), "1.5 min");
}

}  // namespace
}  // namespace arbc::dds
