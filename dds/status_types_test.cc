// The live status's messages (dds/status_types.h): they lay out as diagnostic_msgs' .msg files,
// their values fit their types, and they survive the trip through CDR.
#include "dds/status_types.h"

#include <gtest/gtest.h>

#include "core/ros2_known_messages.h"
#include "dds/cdr_read.h"
#include "dds/cdr_write.h"
#include "dds/msg_layout.h"

namespace arbc::dds {
namespace {

using namespace std::chrono_literals;

TEST(StatusTypesTest, LayOutAsTheRos2Messages) {
  ros2::MsgLibrary library({}, ros2::known_message_texts());
  for (const model::NamedType& n : status_types().named)
    EXPECT_EQ(layout_problem(n.name, *n.type, n.ros2, library), "") << n.ros2;
}

PortStatus mux_port() {
  PortStatus p;
  p.port = "Base.cmd_vel";
  p.selected = "joy";
  p.message = "joy selected";
  p.level = StatusLevel::Ok;
  p.last_rule = "joy";
  p.last_delivery = 1200ms;
  p.arrived = 7;
  p.delivered = 5;
  p.dropped[static_cast<int>(DropReason::NotSelected)] = 2;
  p.rules.resize(2);
  p.rules[0].rule = "joy";
  p.rules[0].source = "Joy.cmd_vel";
  p.rules[0].selected = true;
  p.rules[1].rule = "nav";
  p.rules[1].source = "Nav.cmd_vel";
  p.rules[1].blocked = "held by joy's hold";
  return p;
}

// What a ROS 2 program reads: the value written as CDR and read back is the value.
Value through_cdr(const Type& t, const Value& v) {
  std::vector<uint8_t> bytes;
  std::string error;
  EXPECT_TRUE(cdr_write(t, v, &bytes, &error)) << error;
  Value back;
  CdrRead read = cdr_read(t, bytes.data(), static_cast<uint32_t>(bytes.size()), &back);
  EXPECT_TRUE(read.ok) << read.why;
  return back;
}

std::string value_of(const Value& status, const std::string& key) {
  for (const Value& kv : status["values"].as_list())
    if (kv["key"].as_string() == key) return kv["value"].as_string();
  return "(no key " + key + ")";
}

TEST(StatusTypesTest, ALatchedStatusNamesTheSelectedRuleAndWhyNotTheOthers) {
  Value v = latched_status_value(mux_port(), "mux");
  std::string why;
  ASSERT_TRUE(conforms(v, *status_types().status, &why)) << why;
  Value back = through_cdr(*status_types().status, v);
  EXPECT_EQ(back, v);
  EXPECT_EQ(back["name"].as_string(), "mux: Base.cmd_vel");
  EXPECT_EQ(back["level"].as_int(), 0);
  EXPECT_EQ(value_of(back, "selected"), "joy");
  EXPECT_EQ(value_of(back, "rule joy"), "selected");
  EXPECT_EQ(value_of(back, "rule nav"), "held by joy's hold");
  EXPECT_EQ(value_of(back, "arrived"), "(no key arrived)");  // counters change: not latched
}

TEST(StatusTypesTest, DiagnosticsCarryTheCountersAndTheStamp) {
  PortStatus p = mux_port();
  p.level = StatusLevel::Warn;
  Value v = diagnostic_array_value({p}, "mux", 1500ms, 1'700'000'000'250'000'000ns);
  std::string why;
  ASSERT_TRUE(conforms(v, *status_types().array, &why)) << why;
  Value back = through_cdr(*status_types().array, v);
  EXPECT_EQ(back, v);
  EXPECT_EQ(back["header"]["stamp"]["sec"].as_int(), 1'700'000'000);
  EXPECT_EQ(back["header"]["stamp"]["nanosec"].as_int(), 250'000'000);
  const Value& status = back["status"][size_t{0}];
  EXPECT_EQ(status["level"].as_int(), 1);
  EXPECT_EQ(value_of(status, "arrived"), "7");
  EXPECT_EQ(value_of(status, "delivered"), "5");
  EXPECT_EQ(value_of(status, "dropped not-selected"), "2");
  EXPECT_EQ(value_of(status, "dropped queue-full"), "(no key dropped queue-full)");
  EXPECT_EQ(value_of(status, "last delivery"), "300ms ago by joy");
}

// `arbc status` reads it back as one line.
TEST(StatusTypesTest, AStatusReadsBackAsALine) {
  PortStatus p = mux_port();
  p.level = StatusLevel::Warn;
  Value v = diagnostic_array_value({p}, "mux", 1500ms, 0ns);
  EXPECT_EQ(status_line(v["status"][size_t{0}]),
            "mux: Base.cmd_vel  WARN  joy selected | nav: held by joy's hold  [5 of 7 delivered; "
            "dropped not-selected 2; last delivery 300ms ago by joy]");
}

TEST(StatusTypesTest, DefaultTopicFollowsRos2Names) {
  EXPECT_EQ(default_status_topic("mux", "Base.cmd_vel"), "/arbc/mux/status/Base/cmd_vel");
}

}  // namespace
}  // namespace arbc::dds
