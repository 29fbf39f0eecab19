// Parses Lua 5.4 source into lua_ast.h (the grammar of the Lua 5.4 manual, section 9).
// Used to follow the paths of YARP monitor scripts; the script is never run by this parser.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "import/yarp/lua_ast.h"

namespace arbc::yarp {

// The main chunk as a vararg function. On a syntax error returns nullptr and sets *err to
// "LINE: what is wrong". Nesting deeper than a fixed limit is an error, not a stack overflow.
std::shared_ptr<LuaFunction> parse_lua(std::string_view source, std::string* err);

}  // namespace arbc::yarp
