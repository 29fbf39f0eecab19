#include "import/yarp/carrier.h"

#include <gtest/gtest.h>

namespace arbc::yarp {
namespace {

TEST(Carrier, ReadsAPortMonitorCarrier) {
  Carrier c;
  std::string err;
  ASSERT_TRUE(parse_carrier("tcp+recv.portmonitor+type.lua+file.ball+context.demo", &c, &err));
  EXPECT_EQ(c.base, "tcp");
  EXPECT_TRUE(c.monitor);
  EXPECT_FALSE(c.send_monitor);
  EXPECT_EQ(c.type, "lua");
  EXPECT_EQ(c.file, "ball");
  EXPECT_EQ(c.context, "demo");
  EXPECT_FALSE(c.constraint);
}

TEST(Carrier, PlainAndDefaults) {
  Carrier c;
  std::string err;
  ASSERT_TRUE(parse_carrier("", &c, &err));
  EXPECT_EQ(c.base, "tcp");
  EXPECT_FALSE(c.monitor);
  ASSERT_TRUE(parse_carrier("udp+recv.portmonitor+constraint.e_ball", &c, &err));
  EXPECT_EQ(c.base, "udp");
  EXPECT_EQ(c.file, "modifier");  // YARP's default file name
  EXPECT_EQ(c.constraint, "e_ball");
  ASSERT_TRUE(parse_carrier("tcp+send.portmonitor+file.x", &c, &err));
  EXPECT_TRUE(c.send_monitor);
  EXPECT_FALSE(c.monitor);
}

TEST(Carrier, ADotInAValueIsAnError) {
  Carrier c;
  std::string err;
  EXPECT_FALSE(parse_carrier("tcp+recv.portmonitor+type.lua+file.ball.lua", &c, &err));
  EXPECT_NE(err.find("without its .lua extension"), std::string::npos) << err;
  EXPECT_FALSE(parse_carrier("+recv.portmonitor", &c, &err));
  EXPECT_FALSE(parse_carrier("tcp++file.x", &c, &err));
}

}  // namespace
}  // namespace arbc::yarp
