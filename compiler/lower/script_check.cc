#include "compiler/lower/script_check.h"

#include <lua.hpp>

namespace arbc::lower {

std::string check_lua_syntax(const std::string& text, const std::string& chunk_name) {
  lua_State* L = luaL_newstate();
  if (!L) return "out of memory";
  std::string error;
  // Compiles without running: a syntax check only.
  if (luaL_loadbuffer(L, text.data(), text.size(), ("@" + chunk_name).c_str()) != LUA_OK)
    error = lua_tostring(L, -1) ? lua_tostring(L, -1) : "unknown error";
  lua_close(L);
  return error;
}

}  // namespace arbc::lower
