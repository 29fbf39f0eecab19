// Spelling values and names as Lua 5.4 source text. Everything here is deterministic: the same
// input always gives the same bytes, so generated monitors are byte-identical across builds.
#pragma once

#include <string>
#include <string_view>

namespace arbc::codegen {

// A Lua string literal in double quotes; every byte that is not printable ASCII, and the quote
// and backslash, is escaped, so the literal is valid whatever the spec string holds.
std::string lua_string(std::string_view text);

// A float literal that reads back as the same double and is a Lua float ("0.4", "5.0",
// "1e+100"); infinities and NaN are spelled as expressions ("(1/0)", "(0/0)").
std::string lua_float(double value);

// A spec identifier as a Lua local name. Names that are Lua keywords or names the generated
// code reserves, and names ending in '_', get a '_' appended: the mapping is one-to-one and
// never yields a reserved name, so a spec variable cannot capture a builtin.
std::string lua_local_name(std::string_view spec_name);

// Field access suffix: ".pos" for a plain name, "[\"end\"]" for a Lua keyword.
std::string lua_field(std::string_view field);

// Table constructor key: "pos = " or "[\"end\"] = ".
std::string lua_table_key(std::string_view field);

bool is_lua_keyword(std::string_view name);

// Text safe inside a Lua line comment: newlines become spaces.
std::string lua_comment_text(std::string_view text);

}  // namespace arbc::codegen
