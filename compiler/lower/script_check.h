// Checks hand-written Lua (`script "file.lua"`) at build time, so a syntax error is a build
// diagnostic with the script's file and line rather than a monitor failing at run time.
#pragma once

#include <string>

struct lua_State;

namespace arbc::lower {

// True when `text` compiles as a Lua 5.4 chunk; otherwise false and Lua's message in `err`
// ("x.lua:3: ...").
bool check_lua_syntax(const std::string& text, const std::string& chunk_name, std::string* err);

// The same check for many chunks, reusing one Lua state (code generation checks every monitor
// it writes; a fresh state per chunk would cost more than the compiling).
class LuaSyntaxChecker {
 public:
  LuaSyntaxChecker();
  ~LuaSyntaxChecker();
  LuaSyntaxChecker(const LuaSyntaxChecker&) = delete;
  LuaSyntaxChecker& operator=(const LuaSyntaxChecker&) = delete;
  bool check(const std::string& text, const std::string& chunk_name, std::string* err);

 private:
  lua_State* L_;
};

}  // namespace arbc::lower
