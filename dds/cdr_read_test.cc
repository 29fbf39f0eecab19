// The mediator's CDR reader (dds/cdr_read.h) against Fast-DDS's own decoder: random values of
// types of every shape at their edges, written by Fast-DDS (to_wire, serialize), read both ways,
// must be the same value; big-endian bytes too, which Fast-DDS on this machine never writes. And
// its writer (dds/cdr_write.h) against Fast-DDS's encoder: the same bytes.
#include "dds/cdr_read.h"

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicPubSubType.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "dds/cdr_write.h"
#include "dds/float32_bits.h"
#include "dds/topic_type.h"
#include "dds/wire_values.h"

namespace arbc::dds {
namespace {

namespace ft = eprosima::fastrtps::types;

// Values of type t at their edges: each width's extremes, NaN, infinities, -0.0, the least
// subnormal, empty and long lists (a fixed one at its size), empty, non-ASCII and long strings.
class Edges {
 public:
  explicit Edges(uint32_t seed) : rng_(seed) {}

  Value of(const Type& t) {
    switch (t.kind) {
      case Type::Kind::Bool:
        return Value(pick(2) == 1);
      case Type::Kind::Int:
        return integer(t);
      case Type::Kind::Float:
        return real(t.bits);
      case Type::Kind::String:
        return string(t.size);
      case Type::Kind::Vec3:
        return Value::vec3(real(64).as_float(), real(64).as_float(), real(64).as_float());
      case Type::Kind::List: {
        size_t n = t.fixed ? t.size : pick(4) == 0 ? 0 : pick(t.size > 0 ? t.size + 1 : 40);
        ValueList items;
        for (size_t i = 0; i < n; ++i) items.push_back(of(*t.element));
        return Value(std::move(items));
      }
      case Type::Kind::Record: {
        ValueRecord fields;
        for (const Field& f : t.fields) fields.emplace(f.name, of(*f.type));
        return Value(std::move(fields));
      }
    }
    return Value();
  }

 private:
  size_t pick(size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng_); }
  Value integer(const Type& t) {
    if (t.is_unsigned && t.bits == 64) {  // its bits: 2^64 - 1 is -1
      int64_t edges[] = {0, 1, -1, std::numeric_limits<int64_t>::min(), 42};
      return Value(edges[pick(5)]);
    }
    int64_t lo = t.is_unsigned ? 0 : -(int64_t{1} << (t.bits - 1));
    int64_t hi = t.bits == 64 ? std::numeric_limits<int64_t>::max()
                              : (int64_t{1} << (t.bits - (t.is_unsigned ? 0 : 1))) - 1;
    if (t.bits == 64 && !t.is_unsigned) lo = std::numeric_limits<int64_t>::min();
    int64_t edges[] = {lo, hi, 0, t.is_unsigned ? 1 : -1, lo + 1};
    return Value(edges[pick(5)]);
  }
  Value real(int bits) {
    double edges[] = {std::numeric_limits<double>::quiet_NaN(),
                      std::numeric_limits<double>::infinity(),
                      -std::numeric_limits<double>::infinity(), -0.0,
                      bits == 32 ? static_cast<double>(std::numeric_limits<float>::max())
                                 : std::numeric_limits<double>::max(),
                      bits == 32 ? static_cast<double>(std::numeric_limits<float>::denorm_min())
                                 : std::numeric_limits<double>::denorm_min(),
                      0.5,
                      // A signalling NaN with a payload: its bits must come through unchanged.
                      bits == 32 ? widen(std::bit_cast<float>(uint32_t{0x7f800001}))
                                 : std::bit_cast<double>(uint64_t{0x7ff0000000000123})};
    return Value(edges[pick(8)]);
  }
  Value string(int bound) {
    std::string edges[] = {"", "base_link", "\xc3\xa9t\xc3\xa9 \xe2\x9c\x93",
                           std::string(300, 'x')};
    std::string s = edges[pick(4)];
    if (bound > 0 && s.size() > static_cast<size_t>(bound)) s.resize(static_cast<size_t>(bound));
    return Value(s);
  }
  std::mt19937 rng_;
};

// A value as text with every float as its 64 bits (JSON would print any NaN as "nan").
std::string bits(const Value& v) {
  switch (v.kind()) {
    case Value::Kind::Float:
      return std::to_string(std::bit_cast<uint64_t>(v.as_float()));
    case Value::Kind::Vec3:
      return bits(Value(v.as_vec3().x())) + "," + bits(Value(v.as_vec3().y())) + "," +
             bits(Value(v.as_vec3().z()));
    case Value::Kind::List: {
      std::string out = "[";
      for (const Value& item : v.as_list()) out += bits(item) + ",";
      return out + "]";
    }
    case Value::Kind::Record: {
      std::string out = "{";
      for (const auto& [name, f] : v.as_record()) out += name + ":" + bits(f) + ",";
      return out + "}";
    }
    default:
      return v.to_json();
  }
}

// What Fast-DDS's own decoder makes of the payload: DynamicData, then from_wire.
Value fastdds_read(const WireType& w, eprosima::fastrtps::rtps::SerializedPayload_t* payload) {
  ft::DynamicPubSubType codec(w.dynamic);
  ft::DynamicData* data = ft::DynamicDataFactory::get_instance()->create_data(w.dynamic);
  Value v;
  std::string error;
  payload->pos = 0;
  EXPECT_TRUE(codec.deserialize(payload, data));
  EXPECT_TRUE(from_wire(w, data, &v, &error)) << error;
  ft::DynamicDataFactory::get_instance()->delete_data(data);
  return v;
}

// Types of every shape: each width, bounded and fixed sequences and strings, nested records.
const char* const kTypes[] = {
    "bool",
    "int8",
    "uint8",
    "int16",
    "uint16",
    "int32",
    "uint32",
    "int64",
    "uint64",
    "float32",
    "float",
    "string",
    "string<5>",
    "vec3",
    "list<float32>",
    "list<int16, 3>",
    "float[9]",
    "{a: int8, b: float, c: uint16, d: string, e: bool, f: int64}",
    "{h: {stamp: {sec: int32, nanosec: uint32}, frame_id: string}, r: list<float32>}",
    "{p: {x: float32}[2], q: list<{s: string<3>, v: vec3}, 2>, u: list<uint64>}",
    "list<list<int8>>",
    "string<4>[3]",
};

// Calls check(text, wire, codec, v) for 60 edge values of each type of kTypes, the wire type
// and its type support made once per type; returns how many values were checked.
int for_each_edge(
    uint32_t seed,
    const std::function<void(const char*, const WireType&, WireTopicType&, const Value&)>& check) {
  model::App app;
  app.name = "edges";
  Deployment deployment;
  Edges edges(seed);
  int checked = 0;
  for (const char* text : kTypes) {
    WireNaming naming(app, deployment);
    std::string error;
    auto wire = naming.port_type("M", "p", parse_type(text), &error);
    EXPECT_TRUE(wire) << text << ": " << error;
    if (!wire) continue;
    WireTopicType codec(wire);
    for (int trial = 0; trial < 60 && !testing::Test::HasFatalFailure(); ++trial, ++checked)
      check(text, *wire, codec, edges.of(*wire->type));
  }
  return checked;
}

TEST(CdrReadTest, ReadsWhatFastDdsReadsAtEveryEdge) {
  int compared = for_each_edge(41, [](const char* text, const WireType& wire, WireTopicType& codec,
                                      const Value& v) {
    auto* out = static_cast<WireSample*>(codec.createData());
    auto* in = static_cast<WireSample*>(codec.createData());
    std::string error;
    EXPECT_TRUE(to_wire(wire, v, out->data, &error)) << text << ": " << error;
    eprosima::fastrtps::rtps::SerializedPayload_t payload(codec.getSerializedSizeProvider(out)());
    EXPECT_TRUE(codec.serialize(out, &payload));
    EXPECT_TRUE(codec.deserialize(&payload, in));
    EXPECT_FALSE(in->bad) << text << ": " << v.to_json();
    Value theirs = fastdds_read(wire, &payload);
    // Bit for bit: NaN equals nothing as a double, -0.0 == 0.0, and a NaN's payload and
    // quiet bit matter (a mediator passes a sensor's bits on).
    EXPECT_EQ(bits(in->value), bits(theirs)) << text;
    EXPECT_EQ(bits(in->value), bits(v)) << text;
    codec.deleteData(out);
    codec.deleteData(in);
  });
  EXPECT_EQ(compared, 60 * static_cast<int>(std::size(kTypes)));
}

// The mediator's writer (dds/cdr_write.h) against Fast-DDS's encoder: the same bytes for the
// same value, encapsulation included, and the sample Fast-DDS sends from them is those bytes.
TEST(CdrWriteTest, WritesWhatFastDdsWritesAtEveryEdge) {
  int compared = for_each_edge(
      43, [](const char* text, const WireType& wire, WireTopicType& codec, const Value& v) {
        auto* theirs = static_cast<WireSample*>(codec.createData());
        auto* ours = static_cast<WireSample*>(codec.createData());
        std::string error;
        EXPECT_TRUE(to_wire(wire, v, theirs->data, &error)) << text << ": " << error;
        eprosima::fastrtps::rtps::SerializedPayload_t expected(
            codec.getSerializedSizeProvider(theirs)());
        EXPECT_TRUE(codec.serialize(theirs, &expected));
        EXPECT_TRUE(cdr_write(*wire.type, v, &ours->bytes, &error)) << text << ": " << error;
        std::vector<uint8_t> want(expected.data, expected.data + expected.length);
        EXPECT_EQ(ours->bytes, want) << text << ": " << v.to_json();
        eprosima::fastrtps::rtps::SerializedPayload_t sent(codec.getSerializedSizeProvider(ours)());
        EXPECT_TRUE(codec.serialize(ours, &sent));
        EXPECT_EQ(std::vector<uint8_t>(sent.data, sent.data + sent.length), want) << text;
        EXPECT_EQ(sent.encapsulation, expected.encapsulation) << text;
        codec.deleteData(theirs);
        codec.deleteData(ours);
      });
  EXPECT_EQ(compared, 60 * static_cast<int>(std::size(kTypes)));
}

// What is no value of its type is refused with a reason, never written.
TEST(CdrWriteTest, RefusesWhatIsNoValueOfTheType) {
  std::vector<uint8_t> out;
  std::string error;
  EXPECT_FALSE(cdr_write(*parse_type("float[3]"), Value::list({1.0, 2.0}), &out, &error));
  EXPECT_EQ(error, "a 3-element array holds 2");
  EXPECT_FALSE(cdr_write(*parse_type("list<int32, 1>"), Value::list({1, 2}), &out, &error));
  EXPECT_EQ(error, "a list bounded to 1 holds 2");
  EXPECT_FALSE(cdr_write(*parse_type("{a: int8, b: string}"), Value::record({{"a", Value(1)}}),
                         &out, &error));
  EXPECT_EQ(error, "field 'b' is missing");
  EXPECT_FALSE(cdr_write(*parse_type("string"), Value(std::string("a\0b", 3)), &out, &error));
  EXPECT_EQ(error, "a string holds a NUL byte, which CDR cannot carry");
}

// Big-endian plain CDR: the encapsulation says which order, and alignment counts from the body.
TEST(CdrReadTest, ReadsBigEndianAndRefusesWhatIsNoValue) {
  model::App app;
  app.name = "big";
  Deployment deployment;
  WireNaming naming(app, deployment);
  std::string error;
  auto wire = naming.port_type("M", "p", parse_type("{a: int16, b: float, c: string<3>}"), &error);
  ASSERT_TRUE(wire) << error;
  // 00 00 | 00 00, then a = -2 (2 bytes), pad to 8, b = 1.5, c = "ok" (length 3 with its NUL).
  std::vector<uint8_t> be = {0, 0, 0, 0, 0xff, 0xfe, 0, 0, 0, 0, 0,   0,   0x3f, 0xf8,
                             0, 0, 0, 0, 0,    0,    0, 0, 0, 3, 'o', 'k', 0};
  Value v;
  CdrRead r = cdr_read(*wire->type, be.data(), static_cast<uint32_t>(be.size()), &v);
  ASSERT_TRUE(r.ok) << r.why;
  EXPECT_EQ(v, Value::record({{"a", Value(-2)}, {"b", Value(1.5)}, {"c", Value("ok")}}));
  EXPECT_EQ(r.used, be.size());
  // A string past its bound, bytes that end early, an encapsulation that is not plain CDR.
  std::vector<uint8_t> long_string = be;
  long_string[23] = 5;
  long_string.insert(long_string.end() - 1, {'a', 'y'});
  EXPECT_FALSE(
      cdr_read(*wire->type, long_string.data(), static_cast<uint32_t>(long_string.size()), &v).ok);
  for (uint32_t cut = 0; cut < be.size() - 1; ++cut)
    EXPECT_FALSE(cdr_read(*wire->type, be.data(), cut, &v).ok) << cut;
  std::vector<uint8_t> pl = be;
  pl[1] = 3;  // PL_CDR_LE: a mutable type's parameter list
  EXPECT_FALSE(cdr_read(*wire->type, pl.data(), static_cast<uint32_t>(pl.size()), &v).ok);
  // A bool is 0 or 1; a sequence's length cannot exceed the bytes left.
  auto flags = naming.port_type("M", "q", parse_type("list<bool>"), &error);
  ASSERT_TRUE(flags) << error;
  std::vector<uint8_t> two = {0, 1, 0, 0, 1, 0, 0, 0, 2};
  EXPECT_FALSE(cdr_read(*flags->type, two.data(), static_cast<uint32_t>(two.size()), &v).ok);
  std::vector<uint8_t> huge = {0, 1, 0, 0, 0xff, 0xff, 0xff, 0x7f, 1};
  EXPECT_FALSE(cdr_read(*flags->type, huge.data(), static_cast<uint32_t>(huge.size()), &v).ok);
}

}  // namespace
}  // namespace arbc::dds
