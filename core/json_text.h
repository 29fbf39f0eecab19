// Deterministic JSON text for traces and Value::to_json: the same input gives the same bytes.
#pragma once

#include <string>
#include <string_view>

namespace arbc {

// Appends s as a JSON string literal with escapes.
void append_json_string(std::string& out, std::string_view s);
// Appends the shortest decimal text that reads back as d ("null" for NaN or infinity);
// integral values keep a ".0".
void append_json_double(std::string& out, double d);

}  // namespace arbc
