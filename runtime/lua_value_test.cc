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

}  // namespace
}  // namespace arbc
