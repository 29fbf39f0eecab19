#include "compiler/lower/script_check.h"

#include <lua.hpp>

namespace arbc::lower {

LuaSyntaxChecker::LuaSyntaxChecker() : L_(luaL_newstate()) {}

LuaSyntaxChecker::~LuaSyntaxChecker() {
  if (L_) lua_close(L_);
}

bool LuaSyntaxChecker::check(const std::string& text, const std::string& chunk_name,
                             std::string* err) {
  if (!L_) {
    *err = "out of memory";
    return false;
  }
  // Compiles without running: a syntax check only.
  bool ok = luaL_loadbuffer(L_, text.data(), text.size(), ("@" + chunk_name).c_str()) == LUA_OK;
  if (!ok) *err = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "unknown error";
  lua_settop(L_, 0);
  return ok;
}

bool check_lua_syntax(const std::string& text, const std::string& chunk_name, std::string* err) {
  return LuaSyntaxChecker().check(text, chunk_name, err);
}

}  // namespace arbc::lower
