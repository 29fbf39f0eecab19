#include "compiler/lower/script_check.h"

#include <lua.hpp>

namespace arbc::lower {

LuaSyntaxChecker::LuaSyntaxChecker() : L_(luaL_newstate()) {}

LuaSyntaxChecker::~LuaSyntaxChecker() {
  if (L_) lua_close(L_);
}

std::string LuaSyntaxChecker::check(const std::string& text, const std::string& chunk_name) {
  if (!L_) return "out of memory";
  std::string error;
  // Compiles without running: a syntax check only.
  if (luaL_loadbuffer(L_, text.data(), text.size(), ("@" + chunk_name).c_str()) != LUA_OK)
    error = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "unknown error";
  lua_settop(L_, 0);
  return error;
}

std::string check_lua_syntax(const std::string& text, const std::string& chunk_name) {
  return LuaSyntaxChecker().check(text, chunk_name);
}

}  // namespace arbc::lower
