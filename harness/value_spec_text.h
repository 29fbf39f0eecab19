// A value as a spec literal, `{ verb: "take", pos: vec3(0.3, 0.1, 0.0) }`, for `arbc test`'s
// failures: the expectation is quoted as written in the spec, so what arrived instead reads in
// the same syntax, its record fields in the order the type declares them, to be compared at a
// glance (JSON with sorted keys, `{"pos":{"x":0.3,...},"verb":"take"}`, could not be).
#pragma once

#include <string>

#include "core/type.h"
#include "core/value.h"

namespace arbc::harness {

// `type` gives the order of record fields (null: the value's own order).
std::string value_spec_text(const Value& v, const Type* type);

}  // namespace arbc::harness
