// A spec record that lists a known ROS 2 message's fields in another order is named before
// anything runs: nothing on the wire would tell.
#include "dds/known_messages.h"

#include <gtest/gtest.h>

namespace arbc::dds {
namespace {

TypePtr vec3() { return Type::scalar(Type::Kind::Vec3); }
TypePtr real() { return Type::scalar(Type::Kind::Float); }

TEST(KnownMessagesTest, ATwistInAnotherOrderIsNamed) {
  TypePtr swapped = Type::record({{"angular", vec3()}, {"linear", vec3()}});
  EXPECT_EQ(field_order_problem("Twist", *swapped, "geometry_msgs/msg/Twist"),
            "the spec's Twist lists its fields angular, linear, but geometry_msgs/msg/Twist has "
            "them in the order linear, angular; the bytes come in the message's order and "
            "nothing on the wire names a field, so each would be read as another: list them in "
            "the message's order");
  // The DDS name, as a deployment may write it, is the same message.
  EXPECT_NE(field_order_problem("Twist", *swapped, "geometry_msgs::msg::dds_::Twist_"), "");
}

TEST(KnownMessagesTest, TheMessagesOrderAndOtherNamesPass) {
  TypePtr twist = Type::record({{"linear", vec3()}, {"angular", vec3()}});
  EXPECT_EQ(field_order_problem("Twist", *twist, "geometry_msgs/msg/Twist"), "");
  TypePtr other = Type::record({{"lin", vec3()}, {"ang", vec3()}});
  EXPECT_EQ(field_order_problem("Twist", *other, "geometry_msgs/msg/Twist"), "");
  TypePtr any = Type::record({{"b", vec3()}, {"a", vec3()}});
  EXPECT_EQ(field_order_problem("Cmd", *any, "my_msgs/msg/Cmd"), "");  // not known
}

// A field that is itself a known message is checked too.
TEST(KnownMessagesTest, ANestedQuaternionInAnotherOrderIsNamed) {
  TypePtr quat = Type::record({{"w", real()}, {"x", real()}, {"y", real()}, {"z", real()}});
  TypePtr pose = Type::record({{"position", vec3()}, {"orientation", quat}});
  EXPECT_EQ(field_order_problem("Pose", *pose, "geometry_msgs/msg/Pose"),
            "the spec's Pose lists the fields of orientation as w, x, y, z, but "
            "geometry_msgs/msg/Quaternion has them in the order x, y, z, w; the bytes come in "
            "the message's order and nothing on the wire names a field, so each would be read "
            "as another: list them in the message's order");
}

}  // namespace
}  // namespace arbc::dds
