// Spec types as Fast-DDS dynamic types, their names on the wire, and values through the real
// CDR encoding and back (the codec every DDS sample goes through).
#include "dds/wire_types.h"

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicTypeMember.h>
#include <fastrtps/types/MemberDescriptor.h>
#include <gtest/gtest.h>

#include <random>

#include "dds/topic_type.h"
#include "dds/wire_values.h"

namespace arbc::dds {
namespace {

namespace ft = eprosima::fastrtps::types;

model::App table_app() {
  model::App app;
  app.name = "table_clean";
  app.types.push_back({"Object", parse_type("{pos: vec3, dist: float}"), {}});
  app.types.push_back({"Cmd", parse_type("{verb: string, pos: vec3}"), {}});
  app.types.push_back({"Status", parse_type("list<string>"), {}});
  return app;
}

std::shared_ptr<const WireType> port_type(WireNaming& n, const std::string& type_text,
                                          const std::string& port = "p") {
  std::string error;
  auto w = n.port_type("M", port, parse_type(type_text), &error);
  EXPECT_TRUE(w) << error;
  return w;
}

// Serializes v with the topic type Fast-DDS uses and decodes it into a fresh sample.
Value round_trip(const std::shared_ptr<const WireType>& wire, const Value& v) {
  WireTopicType codec(wire);
  auto* out = static_cast<WireSample*>(codec.createData());
  auto* in = static_cast<WireSample*>(codec.createData());
  std::string error;
  EXPECT_TRUE(to_wire(*wire, v, out->data, &error)) << error;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(codec.getSerializedSizeProvider(out)());
  EXPECT_TRUE(codec.serialize(out, &payload));
  EXPECT_TRUE(codec.deserialize(&payload, in));
  EXPECT_FALSE(in->bad);
  Value back = in->value;
  codec.deleteData(out);
  codec.deleteData(in);
  return back;
}

TEST(WireNamingTest, TopicsDefaultToModuleSlashPortAndRos2AddsRt) {
  model::App app = table_app();
  Deployment plain, ros;
  ros.ros2 = true;
  ros.topics["PickAndPlace.cmd"] = "/arm/cmd";
  plain.topics["PickAndPlace.cmd"] = "/arm/cmd";
  WireNaming a(app, plain), b(app, ros);
  EXPECT_EQ(a.topic("HeadControl.gaze"), "HeadControl/gaze");
  EXPECT_EQ(b.topic("HeadControl.gaze"), "rt/HeadControl/gaze");
  EXPECT_EQ(a.topic("PickAndPlace.cmd"), "arm/cmd");
  EXPECT_EQ(b.topic("PickAndPlace.cmd"), "rt/arm/cmd");
}

TEST(WireNamingTest, TypeNamesAreMangledAsRos2Does) {
  model::App app = table_app();
  Deployment ros;
  ros.ros2 = true;
  Deployment plain;
  WireNaming r(app, ros), p(app, plain);
  EXPECT_EQ(r.mangle("geometry_msgs/msg/Twist"), "geometry_msgs::msg::dds_::Twist_");
  EXPECT_EQ(p.mangle("geometry_msgs/msg/Twist"), "geometry_msgs::msg::Twist");
  EXPECT_EQ(r.mangle("my::Exact"), "my::Exact");
  EXPECT_EQ(port_type(r, "{verb: string, pos: vec3}")->name, "table_clean::msg::dds_::Cmd_");
  EXPECT_EQ(port_type(p, "{verb: string, pos: vec3}")->name, "table_clean::Cmd");
  EXPECT_EQ(port_type(r, "vec3")->name, "geometry_msgs::msg::dds_::Vector3_");
  EXPECT_EQ(port_type(p, "vec3")->name, "arbc::Vec3");
  EXPECT_EQ(port_type(r, "string")->name, "std_msgs::msg::dds_::String_");
  EXPECT_EQ(port_type(r, "int")->name, "std_msgs::msg::dds_::Int64_");
  EXPECT_EQ(port_type(p, "float")->name, "arbc::Float64");
  EXPECT_EQ(port_type(p, "list<string>")->name, "table_clean::Status");
  EXPECT_EQ(port_type(p, "list<{pos: vec3, dist: float}>")->name, "table_clean::M_p");
  EXPECT_EQ(port_type(p, "{a: int, b: {c: bool}}", "q")->name, "table_clean::M_q");
}

TEST(WireNamingTest, DeploymentTypesOverrideTheNames) {
  model::App app = table_app();
  Deployment ros;
  ros.ros2 = true;
  ros.types["Cmd"] = "arm_msgs/msg/Command";
  ros.types["vec3"] = "geometry_msgs/msg/Point";
  ros.types["string"] = "my_msgs/msg/Text";
  WireNaming r(app, ros);
  auto cmd = port_type(r, "{verb: string, pos: vec3}");
  EXPECT_EQ(cmd->name, "arm_msgs::msg::dds_::Command_");
  // A nested vec3 uses its own mapped name.
  ft::DynamicTypeMember* pos = nullptr;
  std::map<ft::MemberId, ft::DynamicTypeMember*> members;
  cmd->dynamic->get_all_members(members);
  pos = members.at(1);
  EXPECT_EQ(pos->get_name(), "pos");
  EXPECT_EQ(pos->get_descriptor()->get_type()->get_name(), "geometry_msgs::msg::dds_::Point_");
  EXPECT_EQ(port_type(r, "string")->name, "my_msgs::msg::dds_::Text_");
}

// The mapping: bool boolean, int int64, float float64, string string, vec3 a struct of
// float64 x, y, z, list an (unbounded) sequence, a record a struct in declaration order.
TEST(WireTypesTest, StructuresFollowTheMapping) {
  model::App app = table_app();
  Deployment d;
  WireNaming n(app, d);
  auto w = port_type(n, "{z: bool, a: int, m: float, s: string, v: vec3, l: list<int>}");
  std::map<ft::MemberId, ft::DynamicTypeMember*> members;
  w->dynamic->get_all_members(members);
  ASSERT_EQ(members.size(), 6u);
  const char* names[] = {"z", "a", "m", "s", "v", "l"};
  ft::TypeKind kinds[] = {ft::TK_BOOLEAN, ft::TK_INT64,     ft::TK_FLOAT64,
                          ft::TK_STRING8, ft::TK_STRUCTURE, ft::TK_SEQUENCE};
  for (ft::MemberId i = 0; i < 6; ++i) {
    EXPECT_EQ(members.at(i)->get_name(), names[i]);
    EXPECT_EQ(members.at(i)->get_descriptor()->get_kind(), kinds[i]) << names[i];
  }
  std::map<ft::MemberId, ft::DynamicTypeMember*> axes;
  members.at(4)->get_descriptor()->get_type()->get_all_members(axes);
  ASSERT_EQ(axes.size(), 3u);
  EXPECT_EQ(axes.at(0)->get_name(), "x");
  EXPECT_EQ(axes.at(2)->get_descriptor()->get_kind(), ft::TK_FLOAT64);
  // A port that is not a record travels in a struct with one field `data`.
  auto s = port_type(n, "string");
  EXPECT_TRUE(s->wrapped);
  std::map<ft::MemberId, ft::DynamicTypeMember*> wrapped;
  s->dynamic->get_all_members(wrapped);
  ASSERT_EQ(wrapped.size(), 1u);
  EXPECT_EQ(wrapped.at(0)->get_name(), "data");
}

TEST(WireTypesTest, TwoStructuresUnderOneNameAreRefused) {
  model::App app = table_app();
  Deployment d;
  d.types["Cmd"] = "x/msg/Same";
  d.types["Object"] = "x/msg/Same";
  WireNaming n(app, d);
  std::string error;
  ASSERT_TRUE(n.port_type("A", "cmd", parse_type("{verb: string, pos: vec3}"), &error)) << error;
  EXPECT_FALSE(n.port_type("A", "obj", parse_type("{pos: vec3, dist: float}"), &error));
  EXPECT_NE(error.find("two different types would both be x::msg::Same on the wire"),
            std::string::npos)
      << error;
}

TEST(WireValuesTest, ValuesSurviveTheWire) {
  model::App app = table_app();
  Deployment d;
  WireNaming n(app, d);
  Value objects = Value::list({});
  for (int i = 0; i < 150; ++i)  // beyond Fast-DDS's default bound of 100 elements
    objects.push_back(Value::record({{"pos", Value::vec3(i, -i, 0.5)}, {"dist", 0.25 * i}}));
  Value cmd = Value::record({{"verb", std::string(1000, 'v')}, {"pos", Value::vec3(1, 2, 3)}});
  struct Case {
    const char* type;
    Value value;
  } cases[] = {
      {"bool", Value(true)},
      {"int", Value(int64_t{-9007199254740993})},
      {"float", Value(0.1)},
      {"string", Value("Please put the object closer!")},
      {"vec3", Value::vec3(0.5, -1e300, 3)},
      {"list<string>", Value::list({"e_taken", "e_arm_idle"})},
      {"list<{pos: vec3, dist: float}>", objects},
      {"{verb: string, pos: vec3}", cmd},
      {"list<list<int>>", Value::list({Value::list({1, 2}), Value::list({}), Value::list({3})})},
      {"{a: {b: list<bool>}, c: int}",
       Value::record({{"a", Value::record({{"b", Value::list({true, false})}})}, {"c", 4}})},
      {"list<int>", Value::list({})},
  };
  for (const Case& c : cases) {
    auto wire = port_type(n, c.type, "p" + std::to_string(&c - cases));
    EXPECT_EQ(round_trip(wire, c.value), c.value) << c.type;
  }
}

// A sample that does not decode is marked bad, never a crash; a reused sample forgets the
// longer list it held before.
TEST(WireValuesTest, UndecodableBytesAreMarkedBadAndSamplesReuseCleanly) {
  model::App app = table_app();
  Deployment d;
  WireNaming n(app, d);
  auto wire = port_type(n, "list<{pos: vec3, dist: float}>");
  WireTopicType codec(wire);
  auto* out = static_cast<WireSample*>(codec.createData());
  auto* in = static_cast<WireSample*>(codec.createData());
  std::string error;
  Value three = Value::list({});
  for (int i = 0; i < 3; ++i)
    three.push_back(Value::record({{"pos", Value::vec3(i, i, i)}, {"dist", 1.0 * i}}));
  ASSERT_TRUE(to_wire(*wire, three, out->data, &error)) << error;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(4096);
  ASSERT_TRUE(codec.serialize(out, &payload));
  ASSERT_TRUE(codec.deserialize(&payload, in));
  Value one = Value::list({Value::record({{"pos", Value::vec3(9, 9, 9)}, {"dist", 9.0}})});
  ASSERT_TRUE(to_wire(*wire, one, out->data, &error)) << error;
  ASSERT_TRUE(codec.serialize(out, &payload));
  ASSERT_TRUE(codec.deserialize(&payload, in));
  EXPECT_EQ(in->value, one) << in->value.to_json();
  // Truncations and random bytes after a valid encapsulation header.
  std::mt19937 rng(7);
  uint32_t full = payload.length;
  for (uint32_t len = 4; len < full; ++len) {
    payload.length = len;
    EXPECT_TRUE(codec.deserialize(&payload, in));
    EXPECT_TRUE(in->bad) << "a sample cut to " << len << " of " << full << " bytes decoded";
  }
  for (int trial = 0; trial < 200; ++trial) {
    payload.length = 4 + rng() % 64;
    for (uint32_t i = 4; i < payload.length; ++i) payload.data[i] = static_cast<uint8_t>(rng());
    EXPECT_TRUE(codec.deserialize(&payload, in));  // bad or not, no crash and no exception
  }
  codec.deleteData(out);
  codec.deleteData(in);
}

// T[N] is an IDL array, list<T, N> a bounded sequence, string<N> a bounded string: the values
// come back, and an array has no length on the wire (the bytes a fastddsgen `double c[3]` has).
TEST(WireValuesTest, SizedListsAndStringsSurviveTheWire) {
  model::App app = table_app();
  Deployment d;
  WireNaming n(app, d);
  Value three = Value::list({Value(1.5), Value(-0.0), Value(3e300)});
  struct Case {
    const char* type;
    Value value;
  } cases[] = {
      {"float[3]", three},
      {"{cov: float32[4], n: int8}",
       Value::record({{"cov", Value::list({Value(0.5), Value(1.0), Value(-2.0), Value(0.25)})},
                      {"n", Value(int64_t{-3})}})},
      {"list<int, 4>", Value::list({1, 2})},
      {"list<int, 4>", Value::list({})},
      {"string<8>", Value("eightchr")},
      {"{a: vec3}[2]", Value::list({Value::record({{"a", Value::vec3(1, 2, 3)}}),
                                    Value::record({{"a", Value::vec3(4, 5, 6)}})})},
      {"list<string<3>, 2>", Value::list({"abc", ""})},
      {"string<4>[2]", Value::list({"ab", "cdef"})},
      {"list<int>[2]", Value::list({Value::list({1}), Value::list({})})},
  };
  for (const Case& c : cases) {
    auto wire = port_type(n, c.type, "s" + std::to_string(&c - cases));
    EXPECT_EQ(round_trip(wire, c.value), c.value) << c.type;
  }
  // {c: int32[2]}: the encapsulation (4 bytes) and two int32, no length before them.
  auto wire = port_type(n, "{c: int32[2]}", "bytes");
  WireTopicType codec(wire);
  auto* out = static_cast<WireSample*>(codec.createData());
  std::string error;
  ASSERT_TRUE(to_wire(*wire, Value::record({{"c", Value::list({7, 8})}}), out->data, &error))
      << error;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(64);
  ASSERT_TRUE(codec.serialize(out, &payload));
  EXPECT_EQ(payload.length, 12u);
  EXPECT_EQ(payload.data[4], 7);
  EXPECT_EQ(payload.data[8], 8);
  // A value of another size is refused before it reaches the wire.
  EXPECT_FALSE(to_wire(*wire, Value::record({{"c", Value::list({7})}}), out->data, &error));
  codec.deleteData(out);
}

// A sample whose bounded sequence or string is longer than the bound (a publisher whose type
// has another bound, or none) is no value of the port's type: it does not decode.
TEST(WireValuesTest, ASequenceLongerThanItsBoundDoesNotDecode) {
  model::App app = table_app();
  Deployment d;
  struct Case {
    const char* wide;
    const char* narrow;
    Value value;
  } cases[] = {
      {"list<int>", "list<int, 2>", Value::list({1, 2, 3})},
      {"string", "string<2>", Value("abc")},
  };
  for (const Case& c : cases) {
    WireNaming n(app, d), other(app, d);  // both wrap as arbc::String: one naming each
    auto wide = port_type(n, c.wide, "w" + std::to_string(&c - cases));
    auto narrow = port_type(other, c.narrow, "n" + std::to_string(&c - cases));
    ASSERT_TRUE(wide && narrow);
    WireTopicType wide_codec(wide), narrow_codec(narrow);
    auto* out = static_cast<WireSample*>(wide_codec.createData());
    auto* in = static_cast<WireSample*>(narrow_codec.createData());
    std::string error;
    ASSERT_TRUE(to_wire(*wide, c.value, out->data, &error)) << error;
    eprosima::fastrtps::rtps::SerializedPayload_t payload(256);
    ASSERT_TRUE(wide_codec.serialize(out, &payload));
    EXPECT_TRUE(narrow_codec.deserialize(&payload, in));
    EXPECT_TRUE(in->bad) << c.narrow << " decoded " << in->value.to_json();
    wide_codec.deleteData(out);
    narrow_codec.deleteData(in);
  }
}

}  // namespace
}  // namespace arbc::dds
