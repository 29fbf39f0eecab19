// A value written straight as the bytes of a DDS sample: the mediator's encoder, the inverse of
// dds/cdr_read.h. Plain CDR (XCDR1) in the host's byte order, as Fast-DDS 2.9 writes it for a
// final struct: the 4-byte encapsulation (CDR_LE or CDR_BE, options 0), then each primitive
// aligned to its size (8 at most) from the start of the body, a sequence or a string led by its
// uint32 length (a string's counts its NUL), a fixed array as its N elements, a struct (a record,
// vec3) as its members in declaration order.
//
// Writing through Fast-DDS's DynamicData cost one element at a time through its dynamic API
// (docs/benchmarks.md "ROS 2 messages"); dds/cdr_write_test.cc compares these bytes with
// Fast-DDS's on random values of random types, and tests/dds/matrix with fastddsgen programs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/type.h"
#include "core/value.h"

namespace arbc::dds {

// Replaces *out with the sample's bytes for v, a value of `type`; false with *error when v is
// no value of it (a fixed list of another length, a missing field, a string with a NUL byte,
// which CDR cannot carry) and *out is then unspecified.
bool cdr_write(const Type& type, const Value& v, std::vector<uint8_t>* out, std::string* error);

}  // namespace arbc::dds
