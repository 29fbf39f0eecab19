// A sample's bytes read straight into a value of its port's spec type: the mediator's decoder.
// The encoding is plain CDR (XCDR1, little or big endian as the encapsulation says), what Fast-DDS
// 2.9 and ROS 2 write for final structs: each primitive aligned to its size (8 at most) from the
// start of the body, a sequence or a string led by its uint32 length (a string's counts its NUL),
// a fixed array as its N elements, a struct as its members in order. The layout is the spec
// type's (dds/wire_types.h: a port whose type is no struct travels as a struct of one member,
// which CDR lays out as the member alone), which dds/msg_layout.h checks against the message's
// definition. It needs no Fast-DDS: fuzz/cdr_read_fuzz.cc feeds it any bytes.
//
// Reading through Fast-DDS's DynamicData cost a LaserScan of 1,080 ranges 103 M instructions,
// 98.75% of it in Fast-DDS (every element a member of its own, an exception thrown and caught for
// each default value: docs/benchmarks.md "ROS 2 messages"); this reads the same bytes into the
// same value (dds/cdr_read_test.cc compares the two on random values of random types).
#pragma once

#include <cstdint>
#include <string>

#include "core/type.h"
#include "core/value.h"

namespace arbc::dds {

struct CdrRead {
  bool ok = false;
  uint32_t used = 0;  // bytes of the payload the value took (encapsulation included)
  std::string why;    // when not ok: what is wrong with the bytes
};

// Reads the payload (4 bytes of encapsulation, then the body) as a value of `type`. Not ok when the
// bytes end early, a bool is neither 0 nor 1, a bounded sequence or string is longer than its
// bound, or the encapsulation is not plain CDR.
CdrRead cdr_read(const Type& type, const uint8_t* payload, uint32_t length, Value* out);

}  // namespace arbc::dds
