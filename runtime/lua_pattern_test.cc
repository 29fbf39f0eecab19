// The sandbox's string pattern functions (lua_pattern.h, sandbox_strings.h) against Lua 5.4's
// own: the same results and error texts on fixed and random cases; and the work budget that
// Lua's own lacks: a pattern that backtracks without end stops with a clear error.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <lua.hpp>
#include <random>
#include <string>
#include <thread>

#include "runtime/lua_sandbox.h"

namespace arbc {
namespace {

// Serialises the values a call returns, so that two states' answers compare as text.
const char* kSerialise = R"(
  function ser(...)
    local out = {}
    for i = 1, select('#', ...) do
      local v = select(i, ...)
      out[#out + 1] = type(v) .. ':' .. tostring(v)
    end
    return table.concat(out, '|')
  end
  function all_gmatch(s, p, init)
    local got = {}
    for a, b, c in string.gmatch(s, p, init) do
      got[#got + 1] = ser(a, b, c)
      if #got > 40 then break end
    end
    return table.concat(got, ';')
  end
  function probe(s, p)
    return table.concat({
      ser(pcall(string.find, s, p)), ser(pcall(string.find, s, p, 2)),
      ser(pcall(string.find, s, p, -3, true)), ser(pcall(string.match, s, p)),
      ser(pcall(string.match, s, p, 3)), ser(pcall(all_gmatch, s, p)),
      ser(pcall(all_gmatch, s, p, 2)), ser(pcall(string.gsub, s, p, '<%0>')),
      ser(pcall(string.gsub, s, p, '[%1]', 2)), ser(pcall(string.gsub, s, p, {a = 'A', b = false})),
      ser(pcall(string.gsub, s, p, function(x, y) return y and x .. y or nil end)),
      ser(pcall(string.gsub, s, p, 7)), ser(pcall(string.gsub, s, p, '%%%'))}, '\n')
  end
)";

// The answers of Lua's own library (a plain state with every library).
class LuaOwn {
 public:
  LuaOwn() : L_(luaL_newstate()) {
    luaL_openlibs(L_);
    // Named as the sandbox names its chunks, so that error positions compare too.
    EXPECT_EQ(luaL_loadbuffer(L_, kSerialise, std::strlen(kSerialise), "@serialise"), LUA_OK);
    EXPECT_EQ(lua_pcall(L_, 0, 0, 0), LUA_OK);
  }
  ~LuaOwn() { lua_close(L_); }
  std::string probe(const std::string& s, const std::string& p) {
    lua_getglobal(L_, "probe");
    lua_pushlstring(L_, s.data(), s.size());
    lua_pushlstring(L_, p.data(), p.size());
    if (lua_pcall(L_, 2, 1, 0) != LUA_OK) return std::string("error: ") + lua_tostring(L_, -1);
    std::string out = lua_tostring(L_, -1);
    lua_settop(L_, 0);
    return out;
  }

 private:
  lua_State* L_;
};

// The same probe in a sandbox, through its protected call (the budgets armed).
class Sandboxed {
 public:
  explicit Sandboxed(SandboxLimits limits = {}) : box_(LuaSandbox::create(limits)) {
    EXPECT_TRUE(box_->run_chunk(kSerialise, "serialise").ok());
  }
  struct Args {
    const std::string* s;
    const std::string* p;
    const char* function;
    std::string result;
  };
  // Calls global `function`(s, p) and returns its string result.
  LuaCall call(const char* function, const std::string& s, const std::string& p,
               std::string* result) {
    Args args{&s, &p, function, {}};
    LuaCall r = box_->protected_call(
        [](lua_State* L) -> int {
          auto* a = static_cast<Args*>(lua_touserdata(L, 1));
          lua_getglobal(L, a->function);
          lua_pushlstring(L, a->s->data(), a->s->size());
          lua_pushlstring(L, a->p->data(), a->p->size());
          lua_call(L, 2, 1);
          size_t len = 0;
          const char* text = lua_tolstring(L, -1, &len);
          if (text) a->result.assign(text, len);
          return 0;
        },
        &args);
    *result = std::move(args.result);
    return r;
  }
  std::string probe(const std::string& s, const std::string& p) {
    std::string out;
    LuaCall r = call("probe", s, p, &out);
    return r.ok() ? out : "error: " + r.error;
  }
  LuaSandbox& box() { return *box_; }

 private:
  std::unique_ptr<LuaSandbox> box_;
};

TEST(LuaPattern, AgreesWithLuaOnTheManualsPatterns) {
  LuaOwn own;
  Sandboxed ours;
  const char* subjects[] = {"",
                            "hello world from Lua",
                            "key = value, k2 = v2",
                            "THE (quick) [brown] fox",
                            "  trim me  ",
                            "a,b,,c",
                            "aaa",
                            "x = f(a(b)c)d",
                            "line1\nline2\x01\xff end",
                            "The big cat"};
  const char* patterns[] = {"",
                            "o",
                            "l+",
                            "%a+",
                            "(%w+)=(%w+)",
                            "(%w+)%s*=%s*(%w+)",
                            "^%s*",
                            "%s*$",
                            "^(.-)%s*$",
                            "%((%a+)%)",
                            "%b()",
                            "%b[]",
                            "%f[%w]%w+",
                            "%f[%a]%a+%f[%A]",
                            "()a()",
                            "(a)(a)%2?",
                            "[%a_][%w_]*",
                            "[^,]*",
                            "%d+",
                            "[0-9]+",
                            "[%]]",
                            "[a-c]+",
                            "[^%s]+",
                            ".-",
                            "x*",
                            "^$",
                            "$",
                            "^",
                            "(h)(e)(l)(l)(o)",
                            "%x+",
                            "%u%l+",
                            "%p",
                            "%c",
                            "[\x80-\xff]",
                            "%z",
                            "a-b",
                            "%",
                            "[a",
                            "(",
                            ")",
                            "%b",
                            "%f",
                            "%1",
                            "(()",
                            "%g+",
                            "[%w-]+",
                            "[-a]",
                            "[]]",
                            "[^]]",
                            ".?",
                            "(.)%1",
                            "^(%s*)$"};
  for (const char* s : subjects) {
    for (const char* p : patterns) {
      SCOPED_TRACE(std::string("subject '") + s + "', pattern '" + p + "'");
      EXPECT_EQ(ours.probe(s, p), own.probe(s, p));
    }
  }
}

// Random patterns from the language's pieces over short subjects: every answer and every
// error text the same as Lua's own.
TEST(LuaPattern, AgreesWithLuaOnRandomPatterns) {
  LuaOwn own;
  Sandboxed ours;
  const char* pieces[] = {"a",     "b",     ".", "%a", "%d", "%s", "%W", "[ab]", "[^a]",
                          "[a-c]", "*",     "+", "-",  "?",  "(",  ")",  "()",   "%1",
                          "%b()",  "%f[a]", "^", "$",  "%",  "[",  "]",  "%%",   " "};
  const char subject_chars[] = "ab(1) ";
  std::mt19937 rng(13);
  for (int i = 0; i < 10000; ++i) {
    std::string p, s;
    int pieces_n = 1 + static_cast<int>(rng() % 6);
    for (int k = 0; k < pieces_n; ++k) p += pieces[rng() % std::size(pieces)];
    int len = static_cast<int>(rng() % 9);
    for (int k = 0; k < len; ++k) s += subject_chars[rng() % (sizeof subject_chars - 1)];
    SCOPED_TRACE("subject '" + s + "', pattern '" + p + "'");
    ASSERT_EQ(ours.probe(s, p), own.probe(s, p));
  }
}

// The pattern of issue 13: 2^40 ways to split the a's between the optional items. Lua's own
// matcher runs for hours inside one C call; ours stops at the step budget.
const std::string kSubject(40, 'a');
std::string catastrophic() {
  std::string p;
  for (int i = 0; i < 40; ++i) p += "a?";
  return p + std::string(40, 'a') + "b";
}

TEST(LuaPattern, BacktrackingWithoutEndStopsAtTheStepBudget) {
  for (const char* function : {"find", "match", "gmatch", "gsub"}) {
    SCOPED_TRACE(function);
    Sandboxed ours;
    std::string code = std::string("function run(s, p) local r = string.") + function + "(s, p, " +
                       (std::string(function) == "gsub" ? "'x'" : "1") +
                       ") if type(r) == 'function' then r() end return 'done' end";
    ASSERT_TRUE(ours.box().run_chunk(code, "run.lua").ok());
    auto start = std::chrono::steady_clock::now();
    std::string out;
    LuaCall r = ours.call("run", kSubject, catastrophic(), &out);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find(std::string("string.") + function +
                           ": work budget of 10000000 steps exceeded"),
              std::string::npos)
        << r.error;
    EXPECT_EQ(r.error.rfind("run.lua:1: ", 0), 0u) << r.error;  // where the script called it
    EXPECT_LT(seconds, 2.0);
  }
}

TEST(LuaPattern, TheScriptsOwnPcallCannotSwallowTheBudget) {
  Sandboxed ours;
  ASSERT_TRUE(ours.box()
                  .run_chunk("function run(s, p)\n"
                             "  for i = 1, 100 do pcall(string.find, s, p) end\n"
                             "  return 'swallowed'\n"
                             "end\n",
                             "pcall.lua")
                  .ok());
  auto start = std::chrono::steady_clock::now();
  std::string out;
  LuaCall r = ours.call("run", kSubject, catastrophic(), &out);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(out, "swallowed");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

TEST(LuaPattern, TheBudgetIsPerCallback) {
  SandboxLimits limits;
  limits.library_steps = 100000;
  Sandboxed ours(limits);
  ASSERT_TRUE(
      ours.box().run_chunk("function run(s, p) return tostring(s:find(p)) end", "r.lua").ok());
  std::string out;
  // Each call fits the budget on its own; many calls in one callback would not.
  for (int i = 0; i < 50; ++i) {
    LuaCall r = ours.call("run", std::string(2000, 'a'), "a+$", &out);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(out, "1");
  }
  // One search that needs more than the budget fails (a*b tries every start: 2 million steps).
  LuaCall r = ours.call("run", std::string(2000, 'a'), "a*b", &out);
  EXPECT_NE(r.error.find("string.find: work budget of 100000 steps exceeded"), std::string::npos)
      << r.error;
}

TEST(LuaPattern, AnInterruptStopsAMatchAtOnce) {
  std::atomic<bool> interrupt{false};
  SandboxLimits limits;
  limits.library_steps = 1LL << 60;  // only the interrupt (or the wall clock) can stop it
  limits.wall_seconds = 60;
  limits.interrupt = &interrupt;
  Sandboxed ours(limits);
  ASSERT_TRUE(
      ours.box().run_chunk("function run(s, p) return tostring(s:find(p)) end", "r.lua").ok());
  std::thread signal([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    interrupt = true;
  });
  auto start = std::chrono::steady_clock::now();
  std::string out;
  LuaCall r = ours.call("run", kSubject, catastrophic(), &out);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  signal.join();
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("r.lua:1: interrupted"), std::string::npos) << r.error;
  EXPECT_LT(seconds, 1.0);
}

TEST(LuaPattern, TheWallClockBudgetHoldsInsideAMatch) {
  SandboxLimits limits;
  limits.library_steps = 1LL << 60;
  limits.wall_seconds = 0.2;
  Sandboxed ours(limits);
  ASSERT_TRUE(
      ours.box().run_chunk("function run(s, p) return tostring(s:find(p)) end", "r.lua").ok());
  std::string out;
  LuaCall r = ours.call("run", kSubject, catastrophic(), &out);
  EXPECT_NE(r.error.find("r.lua:1: wall-clock budget of 200ms exceeded"), std::string::npos)
      << r.error;
}

TEST(LuaPattern, OtherUnboundedLibraryLoopsAreBounded) {
  Sandboxed ours;
  ASSERT_TRUE(ours.box()
                  .run_chunk("function rep() return '[' .. string.rep('', 1 << 60) .. ']' end\n"
                             "function move() table.move({}, 1, 1 << 40, 2) return 'moved' end\n"
                             "function plain(s, p) return tostring(s:find(p, 1, true)) end\n",
                             "lib.lua")
                  .ok());
  std::string out;
  LuaCall r = ours.call("rep", "", "", &out);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(out, "[]");
  r = ours.call("move", "", "", &out);
  EXPECT_NE(r.error.find("lib.lua:2: table.move: work budget of 10000000 steps exceeded"),
            std::string::npos)
      << r.error;
  // Lua's own plain search compares 250,000 bytes at each of 250,000 places here.
  auto start = std::chrono::steady_clock::now();
  r = ours.call("plain", std::string(500000, 'a'), std::string(250000, 'a') + "b", &out);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(out, "nil");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  // Small moves and repetitions still work as in Lua.
  ASSERT_TRUE(ours.box()
                  .run_chunk("function small() local t = table.move({1, 2, 3}, 1, 3, 2) "
                             "return table.concat(t, ',') .. string.rep('ab', 3, '-') end",
                             "small.lua")
                  .ok());
  r = ours.call("small", "", "", &out);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(out, "1,1,2,3ab-ab-ab");
}

}  // namespace
}  // namespace arbc
