// What a type mismatch on a DDS topic tells the user to do: where the name comes from (the
// deployment file's line, or the spec) and what to write there.
#include "dds/type_name_hint.h"

#include <gtest/gtest.h>

#include <vector>

namespace arbc::dds {
namespace {

TEST(TypeNameHintTest, DdsNamesAreWrittenAsTheDeploymentWritesThem) {
  EXPECT_EQ(deployment_type_name("geometry_msgs::msg::dds_::Twist_"), "geometry_msgs/msg/Twist");
  EXPECT_EQ(deployment_type_name("teleop::Twist"), "teleop/Twist");
  EXPECT_EQ(deployment_type_name("Plain"), "Plain");
}

// The mapping that named the type is shown at its line and column, with the program's name to
// write instead.
TEST(TypeNameHintTest, AMappedTypeIsPlacedInTheDeploymentFile) {
  Deployment d;
  d.path = "deploy.json";
  d.text =
      "{\n"
      "  \"ros2\": true,\n"
      "  \"types\": {\"vec3\": \"geometry_msgs/msg/Vector3\",\n"
      "            \"Twist\": \"geometry_msgs/msg/TwistStamped\"}\n"
      "}\n";
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(parse_deployment(d.text, d.path, &d, &errors));
  EXPECT_EQ(type_name_hint(d, "Joy.cmd_vel", "Twist", "geometry_msgs::msg::dds_::Twist_"),
            "; the name is the deployment's, deploy.json:4:13 (\"Twist\": "
            "\"geometry_msgs/msg/TwistStamped\", the type of Joy.cmd_vel): if the program's type "
            "is the same message, write \"geometry_msgs/msg/Twist\" there");
}

TEST(TypeNameHintTest, AnUnmappedTypeIsToBeAddedToTypes) {
  Deployment d;
  d.path = "deploy.json";
  d.text = "{\"ros2\": true}";
  EXPECT_EQ(type_name_hint(d, "Joy.cmd_vel", "Twist", "geometry_msgs::msg::dds_::Twist_"),
            "; this process names Joy.cmd_vel's type Twist after the spec: if the program's "
            "type is the same message, add \"Twist\": \"geometry_msgs/msg/Twist\" to the "
            "deployment's \"types\"");
  EXPECT_EQ(type_name_hint(d, "Joy.cmd_vel", "", "geometry_msgs::msg::dds_::Twist_"),
            "; if the program's type is the same message, give Joy.cmd_vel a named type in the "
            "spec and map it to \"geometry_msgs/msg/Twist\" in the deployment's \"types\"");
}

}  // namespace
}  // namespace arbc::dds
