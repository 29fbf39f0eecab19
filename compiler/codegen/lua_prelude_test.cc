// The builtins are run in a real Lua 5.4 state, not compared as text.
#include "compiler/codegen/lua_prelude.h"

#include <gtest/gtest.h>

#include "compiler/codegen/lua_text.h"
#include "compiler/codegen/testing/lua_monitor_harness.h"
#include "core/builtins.h"

namespace arbc::codegen {
namespace {

using testing::LuaMonitorHarness;
using testing::PortContainer;

// Runs `expr` after the whole prelude, as the body of an update callback, and returns the
// serialised result or the error.
std::string eval(const std::string& expr) {
  std::set<std::string> all = {"arbc_index",  "arbc_equal", "arbc_vadd", "arbc_vsub",
                               "arbc_vscale", "arbc_vdiv",  "arbc_vneg", "arbc_concat"};
  for (const BuiltinInfo& b : kBuiltins) all.emplace(b.lua_helper);
  std::string source =
      lua_prelude(all) + "PortMonitor.update = function(m) return " + expr + " end\n";
  PortContainer port;
  port.set_time(12.5);
  LuaMonitorHarness h(source, "prelude", &port, "c");
  if (!h.load_error().empty()) return "load error: " + h.load_error();
  auto r = h.update("0");
  if (r.reason == "no-value") return "NO VALUE";
  return r.ok ? r.value : "error: " + r.error;
}

TEST(LuaPreludeTest, ListBuiltins) {
  EXPECT_EQ(eval("len({1, 2, 3})"), "3");
  EXPECT_EQ(eval("min_by({{d=3}, {d=1}, {d=2}}, function(o) return o.d end).d"), "1");
  EXPECT_EQ(eval("max_by({{d=3}, {d=1}, {d=3.5}}, function(o) return o.d end).d"), "3.5");
  // Ties keep the first element.
  EXPECT_EQ(eval("min_by({{d=1, n='a'}, {d=1, n='b'}}, function(o) return o.d end).n"), "\"a\"");
}

TEST(LuaPreludeTest, NoValueIsASentinelNotAScriptError) {
  EXPECT_EQ(eval("min_by({}, function(o) return o end)"), "NO VALUE");
  EXPECT_EQ(eval("max_by({}, function(o) return o end)"), "NO VALUE");
  EXPECT_EQ(eval("min({})"), "NO VALUE");
  EXPECT_EQ(eval("arbc_index({10, 20}, 2)"), "NO VALUE");
  EXPECT_EQ(eval("arbc_index({10, 20}, 0)"), "10");
  EXPECT_EQ(eval("arbc_index({10, 20}, -1)"), "NO VALUE");
}

TEST(LuaPreludeTest, NumbersAndVectors) {
  EXPECT_EQ(eval("dist(vec3(1, 2, 3), vec3(4, 6, 3))"), "5.0");
  EXPECT_EQ(eval("norm(vec3(3, 4, 0))"), "5.0");
  EXPECT_EQ(eval("abs(-2.5)"), "2.5");
  EXPECT_EQ(eval("min(3, 1.5, 2)"), "1.5");
  EXPECT_EQ(eval("max({3, 7, 2})"), "7");
  EXPECT_EQ(eval("now()"), "12.5");
  EXPECT_EQ(eval("arbc_vadd(vec3(1, 2, 3), vec3(1, 1, 1))"), "{x=2, y=3, z=4}");
  EXPECT_EQ(eval("arbc_vscale(2, vec3(1, 2, 3))"), "{x=2, y=4, z=6}");
  EXPECT_EQ(eval("arbc_equal({a = vec3(1, 2, 3)}, {a = vec3(1, 2, 3)})"), "true");
  EXPECT_EQ(eval("arbc_equal({1, 2}, {1, 2, 3})"), "false");
  EXPECT_EQ(eval("len(arbc_concat({1}, {2, 3}))"), "3");
}

TEST(LuaPreludeTest, OnlyWhatIsUsedAndWhatItNeeds) {
  EXPECT_EQ(lua_prelude({}), "");
  std::string p = lua_prelude({"min_by"});
  EXPECT_NE(p.find("local function min_by"), std::string::npos);
  EXPECT_NE(p.find("local function arbc_best_by"), std::string::npos);
  EXPECT_NE(p.find("local function arbc_no_value"), std::string::npos);
  EXPECT_EQ(p.find("local function dist"), std::string::npos);
  EXPECT_TRUE(is_builtin("min_by"));
  EXPECT_FALSE(is_builtin("arbc_index"));
  EXPECT_TRUE(is_reserved_lua_name("math"));
  EXPECT_FALSE(is_reserved_lua_name("objects"));
}

// core/builtins.h names a Lua helper for each builtin: the prelude defines it (a builtin added
// to the table without one fails here), and no spec name can shadow it.
TEST(LuaPreludeTest, EveryBuiltinOfTheTableHasItsHelper) {
  for (const BuiltinInfo& b : kBuiltins) {
    std::string helper(b.lua_helper);
    EXPECT_NE(lua_prelude({helper}).find("local function " + helper + "("), std::string::npos)
        << b.name;
    EXPECT_TRUE(is_builtin(helper)) << b.name;
    EXPECT_NE(lua_local_name(helper), helper) << b.name;
  }
}

}  // namespace
}  // namespace arbc::codegen
