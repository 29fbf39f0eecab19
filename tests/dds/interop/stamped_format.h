// One line of exact text per sample of Stamped.idl, printed alike by the program that sends it
// (stamped_pub.cc) and the one that receives it (stamped_sub.cc), so that tests/dds/stamped.py
// compares what arrived with what left as text, byte for byte. Text and not `%g`: a float or a
// double is printed as its bits (NaN's payload, the sign of -0.0 and a denormal are part of the
// value; `%g` would print every NaN as "nan"), an integer in decimal at its own type (a uint64
// above 2^63 - 1 as itself, not as a negative int64), a string as the hex of its bytes (a
// UTF-8 character altered or cut shows). Fields are `path=value`, in the message's order.
#pragma once

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "Stamped.h"

namespace stamped {

inline std::string bits(float v) {
  uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  char text[16];
  std::snprintf(text, sizeof text, "f32:%08" PRIx32, b);
  return text;
}

inline std::string bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  char text[24];
  std::snprintf(text, sizeof text, "f64:%016" PRIx64, b);
  return text;
}

inline std::string bits(bool v) { return v ? "true" : "false"; }

// Integers of every width (int8_t and uint8_t too, which would print as characters).
template <class T>
std::string bits(T v) {
  static_assert(std::is_integral_v<T>);
  if constexpr (std::is_signed_v<T>)
    return std::to_string(static_cast<long long>(v));
  else
    return std::to_string(static_cast<unsigned long long>(v));
}

inline std::string bits(const std::string& s) {
  std::string text = "str:";
  char byte[3];
  for (unsigned char c : s) {
    std::snprintf(byte, sizeof byte, "%02x", c);
    text += byte;
  }
  return text;
}

// `[N:e0,e1,...]`: the length first, so an empty sequence and a lost one differ.
template <class T>
std::string bits(const std::vector<T>& items) {
  std::string text = "[" + std::to_string(items.size()) + ":";
  for (size_t i = 0; i < items.size(); ++i) text += (i ? "," : "") + bits(items[i]);
  return text + "]";
}

inline void field(std::string& line, const char* path, const std::string& value) {
  line += std::string(" ") + path + "=" + value;
}

inline void vector3(std::string& line, const std::string& prefix,
                    const geometry_msgs::msg::dds_::Vector3_& v) {
  field(line, (prefix + ".x").c_str(), bits(v.x()));
  field(line, (prefix + ".y").c_str(), bits(v.y()));
  field(line, (prefix + ".z").c_str(), bits(v.z()));
}

inline std::string line(const geometry_msgs::msg::dds_::TwistStamped_& m) {
  std::string text = "stamped";
  field(text, "header.stamp.sec", bits(m.header().stamp().sec()));
  field(text, "header.stamp.nanosec", bits(m.header().stamp().nanosec()));
  field(text, "header.frame_id", bits(m.header().frame_id()));
  vector3(text, "twist.linear", m.twist().linear());
  vector3(text, "twist.angular", m.twist().angular());
  return text;
}

inline std::string line(const arbc_test::msg::dds_::Widths_& m) {
  std::string text = "widths";
  field(text, "a", bits(m.a()));
  field(text, "b", bits(m.b()));
  field(text, "c", bits(m.c()));
  field(text, "d", bits(m.d()));
  field(text, "e", bits(m.e()));
  field(text, "f", bits(m.f()));
  field(text, "g", bits(m.g()));
  field(text, "h", bits(m.h()));
  field(text, "i", bits(m.i()));
  field(text, "j", bits(m.j()));
  field(text, "k", bits(m.k()));
  field(text, "l", bits(m.l()));
  field(text, "m", bits(m.m()));
  field(text, "n", bits(m.n()));
  field(text, "o", bits(m.o()));
  field(text, "p", bits(m.p()));
  field(text, "q", bits(m.q()));
  field(text, "r", bits(m.r()));
  field(text, "s", bits(m.s()));
  field(text, "t", bits(m.t()));
  field(text, "u", bits(m.u()));
  return text;
}

}  // namespace stamped
