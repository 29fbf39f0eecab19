// Conversion between Values and Lua values (the message form monitors see,
// docs/runtime.md#messages-in-lua).
//
//   bool -> boolean, int -> integer, float -> float, string -> string,
//   vec3 -> table {x=.., y=.., z=..}, list -> sequence {v1, v2, ...},
//   record -> table with string keys {field=..}.
// Back to a Value the conversion is guided by the expected type, which resolves the
// ambiguities of Lua tables: a vec3 may also be written as a 3-sequence {x, y, z}; an empty
// table is an empty list; a Lua integer-valued float is accepted as int, an integer as float.
#pragma once

#include <optional>
#include <string>

#include "core/type.h"
#include "core/value.h"

struct lua_State;

namespace arbc {

// Keeps in L's registry what makes read_value cheaper (the strings "x", "y", "z", so that a
// vec3 is read with three raw lookups instead of a walk over the table); read_value gives the
// same results without it. May raise a Lua error (memory): call it inside a protected call.
void prepare_lua_values(lua_State* L);

// Pushes v onto L's stack. May raise a Lua error (memory): call it inside a protected call.
void push_value(lua_State* L, const Value& v);

// Reads the Lua value at `index` as type t. On mismatch returns nullopt and sets *why
// ("field pos: expected vec3, got string"). Never raises a Lua error: tables are read raw (no
// __index or other metamethod runs) and nothing allocates on the Lua side, so it may be called
// while C++ objects are alive.
std::optional<Value> read_value(lua_State* L, int index, const Type& t, std::string* why);

}  // namespace arbc
