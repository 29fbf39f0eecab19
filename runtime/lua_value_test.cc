#include "runtime/lua_value.h"

#include <gtest/gtest.h>

#include <lua.hpp>

namespace arbc {
namespace {

struct State {
  State() : L(luaL_newstate()) { luaL_openlibs(L); }
  ~State() { lua_close(L); }
  lua_State* L;
};

TEST(LuaValueTest, RoundTripsEveryKind) {
  State s;
  TypePtr t = parse_type("{objs: list<{pos: vec3, dist: float}>, n: int, ok: bool, s: string}");
  ASSERT_TRUE(t);
  Value v = Value::record({
      {"objs", Value::list({Value::record({{"pos", Value::vec3(1, 2, 3)}, {"dist", 0.25}})})},
      {"n", 42},
      {"ok", true},
      {"s", "hi"},
  });
  push_value(s.L, v);
  std::string why;
  auto back = read_value(s.L, -1, *t, &why);
  ASSERT_TRUE(back) << why;
  EXPECT_EQ(*back, v);
}

TEST(LuaValueTest, LuaSideShapeIsWhatGeneratedCodeExpects) {
  State s;
  push_value(s.L, Value::record({{"pos", Value::vec3(1, 2, 3)}, {"l", Value::list({5, 6})}}));
  lua_setglobal(s.L, "m");
  ASSERT_EQ(luaL_dostring(s.L, "return m.pos.x + m.pos.y + m.pos.z + #m.l + m.l[2]"), LUA_OK);
  EXPECT_EQ(lua_tonumber(s.L, -1), 14);
}

TEST(LuaValueTest, AcceptsVec3AsSequenceAndRejectsMismatches) {
  State s;
  std::string why;
  ASSERT_EQ(luaL_dostring(s.L, "return {4, 5, 6}"), LUA_OK);
  auto v = read_value(s.L, -1, *parse_type("vec3"), &why);
  ASSERT_TRUE(v) << why;
  EXPECT_EQ(v->as_vec3(), Eigen::Vector3d(4, 5, 6));
  ASSERT_EQ(luaL_dostring(s.L, "return {verb = 'take'}"), LUA_OK);
  EXPECT_FALSE(read_value(s.L, -1, *parse_type("{verb: string, pos: vec3}"), &why));
  EXPECT_EQ(why, "missing field pos");
  ASSERT_EQ(luaL_dostring(s.L, "return 1.5"), LUA_OK);
  EXPECT_FALSE(read_value(s.L, -1, *parse_type("int"), &why));
  ASSERT_EQ(luaL_dostring(s.L, "return 2.0"), LUA_OK);
  auto two = read_value(s.L, -1, *parse_type("int"), &why);
  ASSERT_TRUE(two);
  EXPECT_EQ(two->as_int(), 2);
  ASSERT_EQ(luaL_dostring(s.L, "local t = {} t[1] = t return t"), LUA_OK);  // cyclic
  EXPECT_FALSE(read_value(s.L, -1, *parse_type("list<list<int>>"), &why));
}

// A protected call of read_value, as the runtime makes it: a Lua error raised inside would
// longjmp over the C++ values being built (a leak LeakSanitizer reports).
struct ReadCall {
  const Type* type;
  std::optional<Value> value;
  std::string why;
};

int read_top(lua_State* L) {
  auto* call = static_cast<ReadCall*>(lua_touserdata(L, 2));
  call->value = read_value(L, 1, *call->type, &call->why);
  return 0;
}

// Returns the Lua status of the call (LUA_OK unless read_value raised).
int read_protected(lua_State* L, const char* chunk, const Type& t, ReadCall* call) {
  call->type = &t;
  lua_pushcfunction(L, read_top);
  if (luaL_dostring(L, chunk) != LUA_OK) return -1;
  lua_pushlightuserdata(L, call);
  int rc = lua_pcall(L, 2, 0, 0);
  lua_settop(L, 0);
  return rc;
}

// A vec3 is read by raw lookups of registry-held keys once prepare_lua_values ran, by a walk
// over the table before: both give the same value or the same error, whatever the table holds.
TEST(LuaValueTest, Vec3ReadsAgreeWithAndWithoutPreparedKeys) {
  const char* tables[] = {
      "{x = 1, y = 2, z = 3}",
      "{4, 5, 6}",
      "{x = 1, 2, 3}",  // named wins: y and z are missing
      "{1, 2, 3, y = 7}",
      "{x = 1, y = 'a', z = 3}",
      "{x = 1, y = 2, z = 3, w = 4, 9}",
      "{}",
      "{1, 2}",
      "{[1.0] = 1, [2] = 2, [3] = 3}",
      "{x = 1.5, y = math.huge, z = -0.0}",
      "setmetatable({}, {__index = function() error('no metamethods') end})",
      "setmetatable({1, 2, 3}, {__index = function() error('no metamethods') end})",
  };
  State plain, prepared;
  prepare_lua_values(prepared.L);
  TypePtr vec3 = parse_type("vec3");
  for (const char* table : tables) {
    std::string text = std::string("return ") + table;
    ASSERT_EQ(luaL_dostring(plain.L, text.c_str()), LUA_OK) << table;
    ASSERT_EQ(luaL_dostring(prepared.L, text.c_str()), LUA_OK) << table;
    std::string why_plain, why_prepared;
    auto a = read_value(plain.L, -1, *vec3, &why_plain);
    auto b = read_value(prepared.L, -1, *vec3, &why_prepared);
    ASSERT_EQ(a.has_value(), b.has_value()) << table;
    if (a) {
      EXPECT_EQ(*a, *b) << table;
    }
    EXPECT_EQ(why_plain, why_prepared) << table;
    lua_settop(plain.L, 0);
    lua_settop(prepared.L, 0);
  }
  // Spot checks of what both say.
  ASSERT_EQ(luaL_dostring(prepared.L, "return {x = 1, 2, 3}"), LUA_OK);
  std::string why;
  EXPECT_FALSE(read_value(prepared.L, -1, *vec3, &why));
  EXPECT_EQ(why, "expected vec3 ({x=, y=, z=} or {x, y, z}), component y is not a number");
  ASSERT_EQ(luaL_dostring(prepared.L, "return {1, 2, 3, y = 7}"), LUA_OK);
  EXPECT_FALSE(read_value(prepared.L, -1, *vec3, &why));
  ASSERT_EQ(luaL_dostring(prepared.L, "return {x = 1, y = 2, z = 3, w = 4, 9}"), LUA_OK);
  auto v = read_value(prepared.L, -1, *vec3, &why);
  ASSERT_TRUE(v) << why;
  EXPECT_EQ(v->as_vec3(), Eigen::Vector3d(1, 2, 3));
}

TEST(LuaValueTest, ReadsTablesRawWithoutRunningMetamethods) {
  State s;
  TypePtr cmd = parse_type("{verb: string, pos: vec3, tags: list<string>}");
  ASSERT_TRUE(cmd);
  const char* raising = "local boom = { __index = function() error('metamethod ran') end }\n";
  ReadCall call;
  // Missing fields are looked up raw: __index never runs, the mismatch is reported.
  std::string chunk =
      std::string(raising) + "return setmetatable({verb = 'take', tags = {'a'}}, boom)";
  ASSERT_EQ(read_protected(s.L, chunk.c_str(), *cmd, &call), LUA_OK) << call.why;
  EXPECT_FALSE(call.value);
  EXPECT_EQ(call.why, "missing field pos");
  // Nested: a vec3 whose x is provided only through __index.
  chunk = std::string(raising) +
          "return {verb = 'take', tags = {}, pos = setmetatable({y = 1, z = 2}, boom)}";
  ASSERT_EQ(read_protected(s.L, chunk.c_str(), *cmd, &call), LUA_OK) << call.why;
  EXPECT_FALSE(call.value);
  EXPECT_EQ(call.why,
            "field pos: expected vec3 ({x=, y=, z=} or {x, y, z}), component x is not a number");
  // A list reads its elements raw too, and a complete record still reads fine.
  chunk = std::string(raising) +
          "return {verb = 'put', tags = setmetatable({'a', 'b'}, boom), pos = {1, 2, 3}}";
  ASSERT_EQ(read_protected(s.L, chunk.c_str(), *cmd, &call), LUA_OK) << call.why;
  ASSERT_TRUE(call.value) << call.why;
  EXPECT_EQ(*call.value, Value::record({{"verb", "put"},
                                        {"pos", Value::vec3(1, 2, 3)},
                                        {"tags", Value::list({"a", "b"})}}));
}

TEST(LuaValueTest, ReportsTheFirstBadFieldInTheTypesOrder) {
  State s;
  TypePtr t = parse_type("{a: int, b: int, c: int}");
  ReadCall call;
  ASSERT_EQ(read_protected(s.L, "return {c = 'x', b = 'y'}", *t, &call), LUA_OK);
  EXPECT_EQ(call.why, "missing field a");
  ASSERT_EQ(read_protected(s.L, "return {c = 'x', b = 'y', a = 1}", *t, &call), LUA_OK);
  EXPECT_EQ(call.why, "field b: expected int, got string");
}

}  // namespace
}  // namespace arbc
