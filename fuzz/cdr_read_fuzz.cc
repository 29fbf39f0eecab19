// Fuzzes the DDS mediator's decoder (dds/cdr_read.h): the bytes a sample carries come from the
// network, from any program on the domain. Input: the first byte picks one of the types below
// (every width, bounded and fixed sequences, strings, nested records, vec3); the rest is the
// payload, encapsulation included. Invariants checked (a violation aborts, so the fuzzer
// records it):
//  - never a crash, a hang or an allocation beyond the payload's size;
//  - a payload read says how many bytes it used, at most the payload, and the value conforms to
//    the type (sized numbers in range, bounded lists and strings within their bounds);
//  - a payload refused says why.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/type.h"
#include "core/value.h"
#include "dds/cdr_read.h"

namespace {

const std::vector<arbc::TypePtr>& types() {
  static const std::vector<arbc::TypePtr> parsed = [] {
    const char* texts[] = {
        "{a: int8, b: uint16, c: int32, d: uint32, e: int64, f: uint64, g: float32, h: float, "
        "i: bool, j: uint8, k: int16}",
        "{s: string, t: string<4>, u: list<string, 2>}",
        "{l: list<int32>, m: list<float32, 3>, n: int16[4], o: uint64[2]}",
        "{header: {stamp: {sec: int32, nanosec: uint32}, frame_id: string}, "
        "ranges: list<float32>, points: list<{x: float, y: float, z: float}, 5>}",
        "{v: vec3, w: list<vec3, 2>, q: {x: float, y: float, z: float, w: float}[2]}",
        "list<string>",
        "string",
        "int32",
        "{nested: list<{name: string, values: list<{key: string, value: string}>}>}",
        "{flags: bool[3], count: uint8, tail: float32}",
    };
    std::vector<arbc::TypePtr> out;
    for (const char* text : texts) {
      std::string error;
      arbc::TypePtr t = arbc::parse_type(text, &error);
      if (!t) std::abort();  // a type above no longer parses: fix the list
      out.push_back(t);
    }
    return out;
  }();
  return parsed;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const arbc::Type& type = *types()[data[0] % types().size()];
  const uint8_t* payload = data + 1;
  uint32_t length = static_cast<uint32_t>(size - 1);
  arbc::Value value;
  arbc::dds::CdrRead r = arbc::dds::cdr_read(type, payload, length, &value);
  if (!r.ok) {
    if (r.why.empty()) std::abort();  // every refusal says why
    return 0;
  }
  if (r.used > length) std::abort();
  std::string why;
  if (!arbc::conforms(value, type, &why)) std::abort();
  return 0;
}
