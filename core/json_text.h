// Deterministic JSON text for traces and Value::to_json: the same input gives the same bytes.
#pragma once

#include <string>
#include <string_view>

#include "core/instant.h"

namespace arbc {

// Appends s as a JSON string literal with escapes.
void append_json_string(std::string& out, std::string_view s);
// Appends the shortest decimal text that reads back as d ("null" for NaN or infinity);
// integral values keep a ".0".
void append_json_double(std::string& out, double d);
// Appends `t` in seconds, exactly (core/instant.h's decimal_seconds), with a ".0" on a whole
// number as above: how app.json writes a duration and a trace an instant.
void append_json_seconds(std::string& out, Nanos t);

// A float *value* (a message field: Value::to_json, so traces) in JSON: append_json_double's
// number, and for the values JSON has no number for the strings "nan", "inf" and "-inf"
// (docs/testing.md#scripted-inputs---inputs). value_from_json (core/value_json.h) reads them
// back. The one definition of that form: whatever writes or reads message values uses these.
void append_json_float(std::string& out, double d);

// A float in spec syntax, as counterexamples print it: the shortest decimal that reads back as
// d ("-0.0" keeps its sign), or nan, inf, -inf (Lua's names) for what has no decimal.
std::string float_spec_text(double d);

}  // namespace arbc
