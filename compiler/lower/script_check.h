// Checks hand-written Lua (`script "file.lua"`) at build time, so a syntax error is a build
// diagnostic with the script's file and line rather than a monitor failing at run time.
#pragma once

#include <string>

struct lua_State;

namespace arbc::lower {

// Empty when `text` compiles as a Lua 5.4 chunk; otherwise Lua's message ("x.lua:3: ...").
std::string check_lua_syntax(const std::string& text, const std::string& chunk_name);

// The same check for many chunks, reusing one Lua state (code generation checks every monitor
// it writes; a fresh state per chunk would cost more than the compiling).
class LuaSyntaxChecker {
 public:
  LuaSyntaxChecker();
  ~LuaSyntaxChecker();
  LuaSyntaxChecker(const LuaSyntaxChecker&) = delete;
  LuaSyntaxChecker& operator=(const LuaSyntaxChecker&) = delete;
  std::string check(const std::string& text, const std::string& chunk_name);

 private:
  lua_State* L_;
};

}  // namespace arbc::lower
