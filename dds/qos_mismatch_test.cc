// What a QoS mismatch on a DDS topic tells the user to do: the setting to write in the
// deployment file, and where.
#include "dds/qos_mismatch.h"

#include <gtest/gtest.h>

#include <vector>

namespace arbc::dds {
namespace {

Deployment parsed(const std::string& text) {
  Deployment d;
  std::vector<Diagnostic> errors;
  EXPECT_TRUE(parse_deployment(text, "deploy.json", &d, &errors));
  return d;
}

// A best-effort publisher (ROS 2's sensor-data profile) before arbc's reliable reader: the
// port's setting goes into a "qos" the file does not have yet, so the file is named.
TEST(QosMismatchTest, ABestEffortPublisherAsksForBestEffortOnThePort) {
  Deployment d = parsed("{\"ros2\": true}");
  EXPECT_EQ(qos_mismatch_text(d, {"rt/bumper", "Bumper.state", true, QosPolicy::Reliability, ""}),
            "DDS: QoS mismatch on topic rt/bumper (Bumper.state): a remote publisher offers best "
            "effort reliability, this process's reader requests reliable, so nothing flows "
            "between them; if that is the program's QoS, write \"Bumper.state\": "
            "{\"reliability\": \"best_effort\"} in \"qos\": {\"ports\": ...} of deploy.json "
            "(docs/distributed.md#quality-of-service)");
}

// A latched subscriber behind arbc's volatile writer: the port's own entry is pointed at, and
// the consequence of transient local is said.
TEST(QosMismatchTest, ATransientLocalSubscriberIsPointedAtThePortsEntry) {
  Deployment d = parsed(
      "{\n"
      "  \"qos\": {\"ports\": {\n"
      "    \"Base.cmd_vel\": {\"reliability\": \"reliable\"}}}\n"
      "}\n");
  EXPECT_EQ(qos_mismatch_text(d, {"rt/cmd_vel", "Base.cmd_vel", false, QosPolicy::Durability, ""}),
            "DDS: QoS mismatch on topic rt/cmd_vel (Base.cmd_vel): a remote subscriber requests "
            "transient local durability, this process's writer offers volatile, so nothing "
            "flows between them; if that is the program's QoS, write \"Base.cmd_vel\": "
            "{\"durability\": \"transient_local\"} in \"qos\": {\"ports\": ...} of "
            "deploy.json:3:5 (the subscriber then also gets the last messages written before it "
            "joined) (docs/distributed.md#quality-of-service)");
}

// Without a deployment file there is no place to point at: the option is named.
TEST(QosMismatchTest, WithoutAFileTheOptionIsNamed) {
  Deployment d;
  std::string line =
      qos_mismatch_text(d, {"Nav/cmd_vel", "Nav.cmd_vel", true, QosPolicy::Reliability, ""});
  EXPECT_NE(line.find("of a deployment file (--deploy)"), std::string::npos) << line;
}

// A policy arbc does not set: the program is to use DDS's default.
TEST(QosMismatchTest, AnotherPolicyIsNamed) {
  Deployment d;
  EXPECT_EQ(
      qos_mismatch_text(d, {"rt/odom", "Base.odom", true, QosPolicy::Other, "DEADLINE"}),
      "DDS: QoS mismatch on topic rt/odom (Base.odom): a remote publisher's DEADLINE QoS is "
      "incompatible with this process's (DDS's default for it), so nothing flows between them; "
      "arbc sets only reliability and durability (docs/distributed.md#quality-of-service): give "
      "the program DDS's default DEADLINE");
}

}  // namespace
}  // namespace arbc::dds
