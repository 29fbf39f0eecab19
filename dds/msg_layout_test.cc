// A spec type mapped to a ROS 2 message is checked against the message's definition before
// anything runs (dds/msg_layout.h): nothing on the wire names a field or its width.
#include "dds/msg_layout.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/ros2_known_messages.h"

namespace arbc::dds {
namespace {

namespace fs = std::filesystem;

TypePtr vec3() { return Type::scalar(Type::Kind::Vec3); }
TypePtr real() { return Type::scalar(Type::Kind::Float); }
TypePtr integer() { return Type::scalar(Type::Kind::Int); }
TypePtr text() { return Type::scalar(Type::Kind::String); }

ros2::MsgLibrary builtin() { return ros2::MsgLibrary({}, ros2::known_message_texts()); }

TEST(MsgLayoutTest, ATwistInAnotherOrderIsNamed) {
  ros2::MsgLibrary lib = builtin();
  TypePtr swapped = Type::record({{"angular", vec3()}, {"linear", vec3()}});
  EXPECT_EQ(layout_problem("Twist", *swapped, "geometry_msgs/msg/Twist", lib),
            "the spec's Twist does not lay out as geometry_msgs/msg/Twist: the spec lists its "
            "fields angular, linear, but geometry_msgs/msg/Twist has them in the order linear, "
            "angular; the bytes come in the message's order and nothing on the wire names a "
            "field, so each would be read as another: list them in the message's order");
  // The DDS name, as a deployment may write it, is the same message.
  EXPECT_NE(layout_problem("Twist", *swapped, "geometry_msgs::msg::dds_::Twist_", lib), "");
}

TEST(MsgLayoutTest, TheMessagesLayoutPassesWhateverTheNames) {
  ros2::MsgLibrary lib = builtin();
  TypePtr twist = Type::record({{"linear", vec3()}, {"angular", vec3()}});
  EXPECT_EQ(layout_problem("Twist", *twist, "geometry_msgs/msg/Twist", lib), "");
  TypePtr other = Type::record({{"lin", vec3()}, {"ang", vec3()}});
  EXPECT_EQ(layout_problem("Twist", *other, "geometry_msgs/msg/Twist", lib), "");
  TypePtr any = Type::record({{"b", vec3()}, {"a", vec3()}});
  EXPECT_EQ(layout_problem("Cmd", *any, "my_msgs/msg/Cmd", lib), "");  // not found: unchecked
  EXPECT_EQ(layout_problem("vec3", *vec3(), "geometry_msgs/msg/Point", lib), "");
  EXPECT_NE(layout_problem("vec3", *vec3(), "geometry_msgs/msg/Point32", lib), "");
}

TEST(MsgLayoutTest, ANestedQuaternionInAnotherOrderIsNamed) {
  ros2::MsgLibrary lib = builtin();
  TypePtr quat = Type::record({{"w", real()}, {"x", real()}, {"y", real()}, {"z", real()}});
  TypePtr pose = Type::record({{"position", vec3()}, {"orientation", quat}});
  std::string why = layout_problem("Pose", *pose, "geometry_msgs/msg/Pose", lib);
  EXPECT_NE(why.find("the spec lists the fields of orientation as w, x, y, z, but "
                     "geometry_msgs/msg/Quaternion has them in the order x, y, z, w"),
            std::string::npos)
      << why;
}

// The case: a TwistStamped whose stamp is written with `int` fields is 16 bytes where
// ROS 2's is 8 (int32 sec, uint32 nanosec): every sample would be read wrong.
TEST(MsgLayoutTest, AStampOfIntsIsNotAnInt32AndAUint32) {
  ros2::MsgLibrary lib = builtin();
  TypePtr time = Type::record({{"sec", integer()}, {"nanosec", integer()}});
  TypePtr header = Type::record({{"stamp", time}, {"frame_id", text()}});
  TypePtr twist = Type::record({{"linear", vec3()}, {"angular", vec3()}});
  TypePtr stamped = Type::record({{"header", header}, {"twist", twist}});
  EXPECT_EQ(layout_problem("TwistStamped", *stamped, "geometry_msgs/msg/TwistStamped", lib),
            "the spec's TwistStamped does not lay out as geometry_msgs/msg/TwistStamped: "
            "header.stamp.sec is int (int64, 8 bytes) in the spec and int32 (4 bytes) in the "
            "message: declare it int32");
  // Declared at ROS 2's widths, it lays out: int32 sec, uint32 nanosec.
  TypePtr stamp =
      Type::record({{"sec", Type::number("int32")}, {"nanosec", Type::number("uint32")}});
  TypePtr exact = Type::record(
      {{"header", Type::record({{"stamp", stamp}, {"frame_id", text()}})}, {"twist", twist}});
  EXPECT_EQ(layout_problem("TwistStamped", *exact, "geometry_msgs/msg/TwistStamped", lib), "");
  // One width off is named with both widths: a uint32 is not an int32, nor a byte a char8.
  TypePtr swapped =
      Type::record({{"sec", Type::number("uint32")}, {"nanosec", Type::number("uint32")}});
  TypePtr off = Type::record(
      {{"header", Type::record({{"stamp", swapped}, {"frame_id", text()}})}, {"twist", twist}});
  std::string why = layout_problem("TwistStamped", *off, "geometry_msgs/msg/TwistStamped", lib);
  EXPECT_NE(why.find("header.stamp.sec is uint32 (4 bytes) in the spec and int32 (4 bytes) in "
                     "the message: declare it int32"),
            std::string::npos)
      << why;
  TypePtr headerless = Type::record({{"twist", twist}});
  EXPECT_NE(layout_problem("TwistStamped", *headerless, "geometry_msgs/msg/TwistStamped", lib)
                .find("has 1 fields (twist) and geometry_msgs/msg/TwistStamped has 2"),
            std::string::npos);
}

class MsgPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("arbc-msg-path-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& rel, const std::string& text) {
    fs::create_directories((dir_ / rel).parent_path());
    std::ofstream(dir_ / rel) << text;
  }
  fs::path dir_;
};

// A .msg file on the path is the definition, before the built-in one; the messages it uses are
// found there too, and a list is a sequence, never a fixed array: T[N] is, at its size.
TEST_F(MsgPathTest, TheFileOnThePathIsTheDefinition) {
  write("my_msgs/msg/Scan.msg",
        "# a scan\nstd_msgs/Header header  # its stamp\nfloat64[] ranges\nfloat64[3] origin\n"
        "int64 MAX_RANGES=1080\n");
  write("std_msgs/msg/Header.msg", "string frame_id\n");  // not ROS 2's: the path wins
  ros2::MsgLibrary lib({dir_.string()}, ros2::known_message_texts());
  TypePtr ok = Type::record({{"header", Type::record({{"frame_id", text()}})},
                             {"ranges", Type::list(real())},
                             {"origin", Type::list(real())}});
  std::string why = layout_problem("Scan", *ok, "my_msgs/msg/Scan", lib);
  EXPECT_NE(why.find("origin is list<float> in the spec and float64[3] in the message, a fixed "
                     "array of 3, which has no length on the wire where a list has one: declare "
                     "it float[3]"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find((dir_ / "my_msgs/msg/Scan.msg").string()), std::string::npos) << why;
  auto scan = [&](TypePtr ranges, TypePtr origin) {
    return Type::record({{"header", Type::record({{"frame_id", text()}})},
                         {"ranges", std::move(ranges)},
                         {"origin", std::move(origin)}});
  };
  EXPECT_EQ(layout_problem("Scan", *scan(Type::list(real()), Type::sized_list(real(), 3, true)),
                           "my_msgs/msg/Scan", lib),
            "");
  EXPECT_NE(layout_problem("Scan", *scan(Type::list(real()), Type::sized_list(real(), 4, true)),
                           "my_msgs/msg/Scan", lib),
            "");
  why = layout_problem("Scan",
                       *scan(Type::sized_list(real(), 3, true), Type::sized_list(real(), 3, true)),
                       "my_msgs/msg/Scan", lib);
  EXPECT_NE(why.find("ranges is float[3] in the spec and float64[] in the message, a sequence"),
            std::string::npos)
      << why;
  // A bound is not on the wire: list<float, 8> lays out as float64[].
  EXPECT_EQ(
      layout_problem("Scan",
                     *scan(Type::sized_list(real(), 8, false), Type::sized_list(real(), 3, true)),
                     "my_msgs/msg/Scan", lib),
      "");
}

TEST_F(MsgPathTest, MalformedCyclicAndMissingDefinitionsAreSaidWithTheirPlace) {
  write("a/msg/Bad.msg", "float64 x\nfloat64[-2] y\n");
  write("a/msg/Loop.msg", "a/Loop next\n");
  write("a/msg/Uses.msg", "b/Missing m\n");
  ros2::MsgLibrary lib({dir_.string()});
  TypePtr one = Type::record({{"x", real()}});
  std::string bad = layout_problem("Bad", *one, "a/msg/Bad", lib);
  EXPECT_NE(bad.find("Bad.msg:2:1: an array's size is a positive whole number"), std::string::npos)
      << bad;
  std::string loop = layout_problem("Loop", *one, "a/msg/Loop", lib);
  EXPECT_NE(loop.find("a/msg/Loop uses itself through a/msg/Loop"), std::string::npos) << loop;
  std::string missing = layout_problem("Uses", *one, "a/msg/Uses", lib);
  EXPECT_NE(missing.find("field 'm' is a b/msg/Missing, which no .msg file on the message path "
                         "defines"),
            std::string::npos)
      << missing;
}

}  // namespace
}  // namespace arbc::dds
