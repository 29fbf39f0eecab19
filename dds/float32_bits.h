// A float32 widened to a double and narrowed back with a NaN's sign and payload moved by hand:
// the hardware's conversions are IEEE operations, which set a signalling NaN's quiet bit
// (0x7f800001 came back 0x7fc00001), and a mediator passes a sensor's bits on unchanged. The
// payload's 23 bits are the double's top 23. Shared by the DDS writer (wire_values.cc) and
// reader (cdr_read.cc).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace arbc::dds {

inline double widen(float f) {
  if (!std::isnan(f)) return f;
  uint32_t b = std::bit_cast<uint32_t>(f);
  return std::bit_cast<double>(uint64_t{b >> 31} << 63 | uint64_t{0x7ff} << 52 |
                               uint64_t{b & 0x7fffffu} << 29);
}

inline float narrow(double x) {
  if (!std::isnan(x)) return static_cast<float>(x);
  uint64_t d = std::bit_cast<uint64_t>(x);
  uint32_t payload = static_cast<uint32_t>(d >> 29) & 0x7fffffu;
  // A double NaN whose payload is all in its low 29 bits: quiet, as the hardware makes it.
  if (payload == 0) payload = 0x400000u;
  return std::bit_cast<float>(static_cast<uint32_t>(d >> 63) << 31 | 0x7f800000u | payload);
}

}  // namespace arbc::dds
