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

}  // namespace arbc
