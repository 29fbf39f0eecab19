// A plain Fast-DDS program (no arbc in it) that publishes ROS 2 TwistStampeds on rt/in/stamped
// and arbc_test Widths on rt/in/widths (Stamped.idl), each sample at the edges of its fields'
// types: every integer width at its minimum and maximum (a uint64 above 2^63 - 1 included),
// NaNs with payloads, quiet and signalling, and with their sign bit set, both infinities, -0.0,
// denormals, the largest finite values, an empty string and sequence, a long sequence (a
// LaserScan's 1080 ranges), UTF-8 strings. It prints each sample it wrote as one line of
// stamped_format.h's text, for tests/dds/stamped.py to compare with what stamped_sub received.
// usage: stamped_pub DOMAIN
#include <cfloat>
#include <chrono>
#include <climits>
#include <cmath>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <limits>
#include <thread>

#include "StampedPubSubTypes.h"
#include "interop_participant.h"
#include "stamped_format.h"

namespace {

using namespace std::chrono_literals;
namespace fdds = eprosima::fastdds::dds;
using eprosima::fastrtps::types::ReturnCode_t;
using geometry_msgs::msg::dds_::TwistStamped_;
using geometry_msgs::msg::dds_::Vector3_;
using Widths = arbc_test::msg::dds_::Widths_;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kInfF = std::numeric_limits<float>::infinity();

// The float or double of these bits (a NaN's payload and sign are chosen this way).
float f32(uint32_t b) {
  float v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}
double f64(uint64_t b) {
  double v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

Vector3_ vec(double x, double y, double z) {
  Vector3_ v;
  v.x(x);
  v.y(y);
  v.z(z);
  return v;
}

TwistStamped_ stamped(int32_t sec, uint32_t nanosec, const std::string& frame, Vector3_ linear,
                      Vector3_ angular) {
  TwistStamped_ m;
  m.header().stamp().sec(sec);
  m.header().stamp().nanosec(nanosec);
  m.header().frame_id(frame);
  m.twist().linear(linear);
  m.twist().angular(angular);
  return m;
}

std::vector<TwistStamped_> stamped_samples() {
  std::string arrows;  // 2,000 bytes of two- and three-byte UTF-8 characters
  for (int i = 0; i < 400; ++i) arrows += "\u00e9\u2192";
  return {
      stamped(INT32_MIN, 0, "", vec(0.0, -0.0, 1.0), vec(f64(1), DBL_MAX, -DBL_MAX)),
      stamped(INT32_MAX, UINT32_MAX, "\u00e9\u2192 base_link",
              vec(f64(0x7ff8000000000001), f64(0xfff8000000000000), kInf),
              vec(-kInf, 0.1, DBL_MIN)),
      stamped(-1, 999999999, arrows, vec(f64(0x7ff0000000000001), f64(0x7ffabcdef0123456), -0.0),
              vec(1e-310, f64(0x8000000000000001), 2.5)),
      stamped(1700000000, 1, "odom", vec(0.5, -0.25, 0.0), vec(0.0, 0.0, 1.5)),
  };
}

// A LaserScan's ranges: 1080 floats, ordinary ones with "no return" (+inf), NaNs with
// payloads, -0.0 and denormals among them.
std::vector<float> scan() {
  std::vector<float> ranges;
  for (uint32_t i = 0; i < 1080; ++i) {
    float r = 0.05f + static_cast<float>(i) * 0.01f;
    if (i % 97 == 0) r = kInfF;
    if (i % 89 == 1) r = f32(0x7fc00000u | i);
    if (i % 83 == 2) r = -0.0f;
    if (i % 79 == 3) r = f32(i);
    ranges.push_back(r);
  }
  ranges.back() = FLT_MAX;
  return ranges;
}

Widths minimum() {
  Widths m;
  m.a(INT8_MIN);
  m.b(0);
  m.c(INT16_MIN);
  m.d(0);
  m.e(INT32_MIN);
  m.f(0);
  m.g(INT64_MIN);
  m.h(0);
  m.i(-FLT_MAX);
  m.j(-DBL_MAX);
  m.o(-0.0);
  m.t(0);
  return m;  // k, l, m, q, r, u empty; n, p 0; s false
}

Widths maximum() {
  Widths m;
  m.a(INT8_MAX);
  m.b(UINT8_MAX);
  m.c(INT16_MAX);
  m.d(UINT16_MAX);
  m.e(INT32_MAX);
  m.f(UINT32_MAX);
  m.g(INT64_MAX);
  m.h(UINT64_MAX);  // 18446744073709551615: -1 as an int64
  m.i(FLT_MAX);
  m.j(DBL_MAX);
  m.k(scan());
  m.l({INT16_MIN, -1, 0, 1, INT16_MAX});
  m.m("\u00e9\u2192");
  m.n(UINT8_MAX);
  m.o(DBL_MAX);
  m.p(UINT8_MAX);
  m.q({0, 1, INT64_MAX, uint64_t{1} << 63, UINT64_MAX});
  m.r({INT8_MIN, -1, 0, 1, INT8_MAX});
  m.s(true);
  m.t(UINT16_MAX);
  m.u({f64(0x7ff800000000beef), f64(0xfff8000000000000), -0.0, f64(1), DBL_MAX, -kInf});
  return m;
}

// Near the middle of each range, and float specials: a quiet NaN with a payload, -NaN, the
// infinities, the smallest and largest denormals, FLT_MIN.
Widths specials() {
  Widths m;
  m.a(-1);
  m.b(1);
  m.c(-1);
  m.d(1);
  m.e(-1);
  m.f(1);
  m.g(-1);
  m.h(uint64_t{1} << 63);  // 9223372036854775808: INT64_MIN's bits
  m.i(f32(0x7fc00123));
  m.j(f64(0x7ff800000000beef));
  m.k({-0.0f, kInfF, -kInfF, f32(1), f32(0x807fffff), FLT_MIN, f32(0xffc00000)});
  m.l({-2, 2});
  m.m(std::string(1000, 'x'));
  m.n(1);
  m.o(-kInf);
  m.p('A');
  m.q({uint64_t{1} << 63});
  m.r({-128});
  m.s(false);
  m.t(1);
  m.u({f64(0x000fffffffffffff), f64(0x8000000000000000)});
  return m;
}

// Signalling NaNs: a conversion (float to double, or an arithmetic operation) sets their quiet
// bit, so a mediator that converts them shows here.
Widths signalling() {
  Widths m = specials();
  m.h((uint64_t{1} << 63) - 1);
  m.i(f32(0x7f800001));
  m.j(f64(0x7ff0000000000001));
  m.k({f32(0x7fa00000), f32(0xff800001), f32(0x7fbfffff)});
  m.m("");
  m.o(f64(0xfff4000000000000));
  m.u({f64(0x7ff4000000000000)});
  return m;
}

std::vector<Widths> widths_samples() {
  Widths denormals = specials();
  denormals.i(f32(0x00000001));
  denormals.j(f64(0x000fffffffffffff));
  denormals.o(kInf);
  Widths zeros = specials();
  zeros.i(-0.0f);
  zeros.j(-0.0);
  zeros.o(0.0);
  return {minimum(), maximum(), specials(), denormals, zeros, signalling()};
}

fdds::DataWriter* writer(fdds::DomainParticipant* p, fdds::Publisher* pub, const char* topic,
                         const char* type) {
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  interop::reliable(qos);
  return pub->create_datawriter(p->create_topic(topic, type, fdds::TOPIC_QOS_DEFAULT), qos);
}

// Writes each sample and prints its line; false when Fast-DDS refuses one.
template <class T>
bool send(fdds::DataWriter* w, std::vector<T> samples) {
  for (T& s : samples) {
    if (!w->write(&s)) return false;
    std::printf("%s\n", stamped::line(s).c_str());
    std::fflush(stdout);
    std::this_thread::sleep_for(50ms);  // no burst: the mediator's queues are not under test
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: stamped_pub DOMAIN\n");
    return 2;
  }
  fdds::DomainParticipant* p = interop::plain_participant(std::atoi(argv[1]), "stamped_pub");
  fdds::TypeSupport(new geometry_msgs::msg::dds_::TwistStamped_PubSubType()).register_type(p);
  fdds::TypeSupport(new arbc_test::msg::dds_::Widths_PubSubType()).register_type(p);
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriter* st = writer(p, pub, "rt/in/stamped", "geometry_msgs::msg::dds_::TwistStamped_");
  fdds::DataWriter* wi = writer(p, pub, "rt/in/widths", "arbc_test::msg::dds_::Widths_");
  if (!interop::matched(st) || !interop::matched(wi)) {
    std::fprintf(stderr, "stamped_pub: no reader on rt/in/stamped or rt/in/widths in 30 s\n");
    return 3;
  }
  std::this_thread::sleep_for(1s);  // the mediator matches the subscriber too
  if (!send(st, stamped_samples()) || !send(wi, widths_samples())) {
    std::fprintf(stderr, "stamped_pub: Fast-DDS refused a sample\n");
    return 3;
  }
  const eprosima::fastrtps::Duration_t ten_seconds(10, 0);
  bool acked = st->wait_for_acknowledgments(ten_seconds) == ReturnCode_t::RETCODE_OK &&
               wi->wait_for_acknowledgments(ten_seconds) == ReturnCode_t::RETCODE_OK;
  std::fprintf(stderr, "stamped_pub: sent every sample%s\n", acked ? "" : ", not all acknowledged");
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return acked ? 0 : 3;
}
