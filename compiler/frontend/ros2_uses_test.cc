// `use ros2`: the types it declares are the messages' definitions, field for field and width for
// width, under the names ros2_uses.h gives; what it cannot declare is an error at the `use`.
#include "compiler/frontend/ros2_uses.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "compiler/frontend/frontend.h"

namespace arbc::frontend {
namespace {

namespace fs = std::filesystem;

// A message path of the test's own: ARBC_MSG_PATH is that folder alone while it lives.
class Ros2UsesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("arbc-ros2-uses-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    setenv("ARBC_MSG_PATH", dir_.c_str(), 1);
    unsetenv("AMENT_PREFIX_PATH");
  }
  void TearDown() override {
    unsetenv("ARBC_MSG_PATH");
    fs::remove_all(dir_);
  }
  void write(const std::string& full, const std::string& text) {
    fs::path p = dir_ / full;
    p += ".msg";
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
  }
  static const ast::TypeDecl* type(const CheckResult& r, const std::string& name) {
    for (const ast::TypeDecl& t : r.spec->types)
      if (t.name == name) return &t;
    return nullptr;
  }
  static std::string errors(const CheckResult& r) {
    std::string s;
    for (const Diagnostic& d : r.diagnostics) s += d.id + ": " + d.message + "\n";
    return s;
  }
  fs::path dir_;
};

constexpr const char* kHead = "app a;\nmodule M { out o: Scan; }\n";

TEST_F(Ros2UsesTest, DeclaresTheMessageAndWhatItUsesAtTheirWidths) {
  write("sensor_msgs/msg/Scan",
        "uint8 KIND=3\nstd_msgs/Header header\nfloat32[] ranges\nuint16[<=4] flags\n"
        "string<=8 label\nbool ok\nbyte b\nchar c\nint8 d\nfloat64[9] cov\n"
        "string<=4[2] tags\n");
  CheckResult r = check_text(std::string(kHead) + "use ros2 sensor_msgs/msg/Scan;\n", "a.spec");
  ASSERT_TRUE(r.ok()) << errors(r);
  const ast::TypeDecl* scan = type(r, "Scan");
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->ros2, "sensor_msgs/msg/Scan");
  EXPECT_EQ(scan->msg_file, (dir_ / "sensor_msgs/msg/Scan.msg").string());
  // Bounded sequences and strings keep their bound, fixed arrays their size; byte and char are
  // uint8 (rosidl).
  EXPECT_EQ(scan->type.resolved->to_string(),
            "{header: {stamp: {sec: int32, nanosec: uint32}, frame_id: string}, "
            "ranges: list<float32>, flags: list<uint16, 4>, label: string<8>, ok: bool, "
            "b: uint8, c: uint8, d: int8, cov: float[9], tags: string<4>[2]}");
  // What it uses is declared too, from arbc's built-in definitions (no file on the path).
  ASSERT_TRUE(type(r, "Header"));
  EXPECT_EQ(type(r, "Header")->ros2, "std_msgs/msg/Header");
  EXPECT_EQ(type(r, "Header")->msg_file, "");
  ASSERT_TRUE(type(r, "Time"));
  EXPECT_EQ(type(r, "Time")->ros2, "builtin_interfaces/msg/Time");
}

TEST_F(Ros2UsesTest, AFileOnThePathWinsOverTheBuiltInDefinition) {
  write("geometry_msgs/msg/Twist", "float32 speed\n");
  CheckResult r = check_text("app a;\nuse ros2 geometry_msgs/Twist;\n", "a.spec");
  ASSERT_TRUE(r.ok()) << errors(r);
  EXPECT_EQ(type(r, "Twist")->type.resolved->to_string(), "{speed: float32}");
}

TEST_F(Ros2UsesTest, AUsedMessageTakesANameTheSpecDoesNotHave) {
  CheckResult r = check_text(
      "app a;\ntype Time = {t: int};\nuse ros2 geometry_msgs/msg/TwistStamped;\n"
      "module M { out o: TwistStamped; out t: Time; }\n",
      "a.spec");
  ASSERT_TRUE(r.ok()) << errors(r);
  EXPECT_EQ(type(r, "Time")->ros2, "");  // the spec's own
  const ast::TypeDecl* stamp = type(r, "builtin_interfaces_Time");
  ASSERT_TRUE(stamp);
  EXPECT_EQ(stamp->ros2, "builtin_interfaces/msg/Time");
  // Used twice (itself, and by TwistStamped): declared once.
  r = check_text(
      "app a;\nuse ros2 geometry_msgs/msg/Twist;\nuse ros2 geometry_msgs/msg/Vector3;\n"
      "use ros2 geometry_msgs/msg/TwistStamped;\n",
      "a.spec");
  ASSERT_TRUE(r.ok()) << errors(r);
  int vectors = 0;
  for (const ast::TypeDecl& t : r.spec->types) vectors += t.ros2 == "geometry_msgs/msg/Vector3";
  EXPECT_EQ(vectors, 1);
  // Each at its own `use` (go to definition leads there), not at the first that needed it.
  EXPECT_EQ(type(r, "Vector3")->loc.line, 3);
  EXPECT_EQ(type(r, "Header")->loc.line, 4);  // needed by TwistStamped only
}

TEST_F(Ros2UsesTest, AUsedMessageNamedLikeASpecTypeIsADuplicate) {
  CheckResult r =
      check_text("app a;\ntype Twist = {v: int};\nuse ros2 geometry_msgs/msg/Twist;\n", "a.spec");
  EXPECT_NE(errors(r).find("duplicate: type 'Twist' is already defined at line 2"),
            std::string::npos)
      << errors(r);
}

TEST_F(Ros2UsesTest, WhatCannotBeDeclaredIsAnErrorAtTheUse) {
  write("bad_msgs/msg/Broken", "float64 x\nint32\n");
  write("bad_msgs/msg/Fixed", "float64[4097] covariance\n");
  write("bad_msgs/msg/Outer", "Fixed inner\nint32 n\n");
  struct Case {
    const char* use;
    const char* says;
  } cases[] = {
      {"use ros2 nav_msgs/msg/Missing;",
       "no definition of nav_msgs/msg/Missing on the message "
       "path; looked in '"},
      {"use ros2 bad_msgs/msg/Broken;", "bad_msgs/msg/Broken cannot be read ("},
      {"use ros2 bad_msgs/msg/Fixed;", "field 'covariance'"},
      {"use ros2 bad_msgs/msg/Outer;", "field 'covariance'"},  // reported once, for Fixed
      {"use ros2 bad_msgs/srv/Trigger;", "'bad_msgs/srv/Trigger' is not a message"},
      {"use rust std/msg/Vec;", "`use rust`: arbc reads ROS 2 message definitions only"},
  };
  for (const Case& c : cases) {
    CheckResult r = check_text(std::string("app a;\n") + c.use + "\n", "a.spec");
    ASSERT_EQ(r.diagnostics.size(), 1u) << c.use << "\n" << errors(r);
    const Diagnostic& d = r.diagnostics[0];
    EXPECT_EQ(d.id, "ros2-message");
    EXPECT_EQ(d.loc.line, 2) << c.use;
    EXPECT_NE(d.message.find(c.says), std::string::npos) << c.use << "\n" << d.message;
  }
  // A .msg file's error notes the file's line.
  CheckResult r = check_text("app a;\nuse ros2 bad_msgs/msg/Broken;\n", "a.spec");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  ASSERT_EQ(r.diagnostics[0].notes.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].notes[0].loc.file.str(), (dir_ / "bad_msgs/msg/Broken.msg").string());
  EXPECT_EQ(r.diagnostics[0].notes[0].loc.line, 2);
}

// A message's constants are the spec's `Type.NAME`, of the type's kind; one that is no value of
// its declared type is an error at the `use`, with a note at its line.
TEST_F(Ros2UsesTest, ConstantsAreReadAsTypeDotName) {
  write("sensor_msgs/msg/Range",
        "uint8 ULTRASOUND=0\nuint8 INFRARED=1\nfloat32 HALF=0.5\nstring FRAME=\"base\"\n"
        "bool ON=true\nuint64 ALL=18446744073709551615\nuint8 radiation_type\nfloat32 range\n"
        "uint64 seq\n");
  std::string spec =
      "app a;\nuse ros2 sensor_msgs/msg/Range;\nmodule S { out r: Range; }\n"
      "module B { in r: Range; }\n"
      "connect S.r -> B.r { accept r.radiation_type == Range.INFRARED and r.range > Range.HALF "
      "and Range.FRAME == \"base\" and Range.ON and r.seq < Range.ALL; }\n";
  CheckResult r = check_text(spec, "a.spec");
  ASSERT_TRUE(r.ok()) << errors(r);
  // Not a constant of the message: an unknown name, as any.
  CheckResult miss = check_text(
      "app a;\nuse ros2 sensor_msgs/msg/Range;\nmodule S { out r: Range; }\n"
      "module B { in r: Range; }\nconnect S.r -> B.r { accept r.radiation_type == Range.SONAR; }\n",
      "a.spec");
  EXPECT_FALSE(miss.ok());
  write("bad_msgs/msg/Consts",
        "uint8 BIG=300\nfloat32 TENTH=0.1\nuint64 HUGE=18446744073709551616\nint32 n\n");
  CheckResult bad = check_text("app a;\nuse ros2 bad_msgs/msg/Consts;\n", "a.spec");
  ASSERT_EQ(bad.diagnostics.size(), 3u) << errors(bad);
  EXPECT_NE(bad.diagnostics[0].message.find("constant 'BIG'"), std::string::npos);
  EXPECT_NE(bad.diagnostics[0].message.find("'300' is not a uint8 (0 to 255)"), std::string::npos)
      << bad.diagnostics[0].message;
  EXPECT_EQ(bad.diagnostics[0].loc.line, 2);
  ASSERT_EQ(bad.diagnostics[0].notes.size(), 1u);
  EXPECT_EQ(bad.diagnostics[0].notes[0].loc.line, 1);
  EXPECT_NE(bad.diagnostics[1].message.find("'0.1' is not a float32 value"), std::string::npos);
  EXPECT_NE(bad.diagnostics[2].message.find("'18446744073709551616' is not a uint64"),
            std::string::npos)
      << bad.diagnostics[2].message;
}

}  // namespace
}  // namespace arbc::frontend
