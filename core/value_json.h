// Values read back from JSON, typed by a port's type: the inverse of Value::to_json (the
// `value` of a trace line, an `arbc run --inputs` line; docs/testing.md#scripted-inputs---inputs).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/type.h"
#include "core/value.h"

namespace arbc {

// The value `j` denotes as a `t`: a number for int/float (an int only when integral; a float may
// also be "nan", "inf" or "-inf", as Value::to_json writes what JSON has no number for), a string,
// a bool, a vec3 as {"x":..,"y":..,"z":..} or [x, y, z], a list as an array, a record as an
// object with exactly the type's fields. On failure *err says where ("field pos.x: expected
// float, got string"), the path from the value's root.
std::optional<Value> value_from_json(const nlohmann::json& j, const Type& t, std::string* err);

// A float value in JSON (core/json_text.h, append_json_float): a number, or one of the strings
// "nan", "inf" and "-inf"; nullopt for anything else.
std::optional<double> json_float(const nlohmann::json& j);

}  // namespace arbc
