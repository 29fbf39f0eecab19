// Checks hand-written Lua (`script "file.lua"`) at build time, so a syntax error is a build
// diagnostic with the script's file and line rather than a monitor failing at run time.
#pragma once

#include <string>

namespace arbc::lower {

// Empty when `text` compiles as a Lua 5.4 chunk; otherwise Lua's message ("x.lua:3: ...").
std::string check_lua_syntax(const std::string& text, const std::string& chunk_name);

}  // namespace arbc::lower
