// Fuzzes the conversion of Lua values to Values, the path every monitor's `update` result
// takes. Input: a port type on the first line, then a Lua expression. The expression runs in a
// bare Lua state (no libraries, an instruction limit); its result is read as that type.
// Invariants checked (a violation aborts, so the fuzzer records it):
//  - a mismatch is reported with a reason, never a crash or a Lua error escaping;
//  - a value that was read converts back to Lua and reads again to an equal value (compared
//    as JSON text, so that a NaN, which equals nothing, counts as itself).
#include <cstdint>
#include <cstdlib>
#include <lua.hpp>
#include <string>

#include "runtime/lua_value.h"

namespace {

struct Input {
  const arbc::Type* type;
  std::string* why;
  std::optional<arbc::Value>* value;
};

// Runs inside lua_pcall, so memory errors raised by the conversions are caught.
int read_then_round_trip(lua_State* L) {
  auto* in = static_cast<Input*>(lua_touserdata(L, 1));
  *in->value = arbc::read_value(L, 2, *in->type, in->why);
  if (!*in->value) {
    if (in->why->empty()) std::abort();  // every mismatch says why
    return 0;
  }
  arbc::push_value(L, **in->value);
  std::string why_again;
  std::optional<arbc::Value> again = arbc::read_value(L, -1, *in->type, &why_again);
  if (!again || again->to_json() != (*in->value)->to_json()) std::abort();
  return 0;
}

void stop_runaway(lua_State* L, lua_Debug*) { luaL_error(L, "instruction limit"); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  size_t newline = text.find('\n');
  if (newline == std::string::npos) return 0;
  arbc::TypePtr type = arbc::parse_type(text.substr(0, newline));
  if (!type) return 0;
  std::string chunk = "return " + text.substr(newline + 1);

  lua_State* L = luaL_newstate();
  lua_sethook(L, stop_runaway, LUA_MASKCOUNT, 100000);
  if (luaL_loadbufferx(L, chunk.data(), chunk.size(), "=fuzz", "t") == LUA_OK &&
      lua_pcall(L, 0, 1, 0) == LUA_OK) {
    std::string why;
    std::optional<arbc::Value> value;
    Input in{type.get(), &why, &value};
    lua_pushcfunction(L, read_then_round_trip);
    lua_pushlightuserdata(L, &in);
    lua_pushvalue(L, -3);
    lua_pcall(L, 2, 0, 0);
  }
  lua_close(L);
  return 0;
}
