// Every function here is a lua_CFunction that may raise Lua errors (a longjmp): none keeps a C++
// object with a destructor alive (the matcher is trivially destructible).
#include "runtime/sandbox_strings.h"

#include <cctype>
#include <cstring>
#include <lua.hpp>
#include <new>
#include <type_traits>

#include "runtime/lua_pattern.h"
#include "runtime/lua_sandbox.h"

namespace arbc {

namespace {

static_assert(std::is_trivially_destructible_v<PatternMatcher>,
              "a longjmp may skip the matcher's destructor");

// The budget a matcher charges: the sandbox's library budget, named by the function.
struct Charge {
  lua_State* L;
  const char* function;
};

bool charge_steps(void* context, int64_t steps) {
  auto* c = static_cast<Charge*>(context);
  return LuaSandbox::charge(c->L, steps, c->function);
}

// Lua's posrelatI: a 1-based start position, negative counting from the end, clamped to 1.
size_t start_index(lua_Integer pos, size_t len) {
  if (pos > 0) return static_cast<size_t>(pos);
  if (pos == 0 || pos < -static_cast<lua_Integer>(len)) return 1;
  return len + static_cast<size_t>(pos) + 1;
}

// Raises the matcher's error: the budget's stop, or a malformed pattern in Lua's words.
int raise_match_error(lua_State* L, const PatternMatcher& m) {
  if (m.budget_stopped()) return LuaSandbox::stop(L);
  return luaL_error(L, "%s", m.error());
}

// Pushes capture i (or, with no captures, the whole match s..e when i is 0).
void push_capture(lua_State* L, const PatternMatcher& m, int i, const char* s, const char* e) {
  if (i >= m.captures()) {
    if (i != 0) luaL_error(L, "invalid capture index %%%d", i + 1);
    lua_pushlstring(L, s, static_cast<size_t>(e - s));
    return;
  }
  const PatternMatcher::Capture& c = m.capture(i);
  if (c.len == PatternMatcher::kUnfinished) luaL_error(L, "unfinished capture");
  if (c.len == PatternMatcher::kPosition) {
    lua_pushinteger(L, (c.init - m.subject()) + 1);
  } else {
    lua_pushlstring(L, c.init, static_cast<size_t>(c.len));
  }
}

// Pushes every capture (the whole match s..e when there are none and s is set).
int push_captures(lua_State* L, const PatternMatcher& m, const char* s, const char* e) {
  int n = m.captures() == 0 && s ? 1 : m.captures();
  luaL_checkstack(L, n, "too many captures");
  for (int i = 0; i < n; ++i) push_capture(L, m, i, s, e);
  return n;
}

// string.find (find) and string.match (!find).
int find_or_match(lua_State* L, bool find) {
  size_t ls, lp;
  const char* s = luaL_checklstring(L, 1, &ls);
  const char* p = luaL_checklstring(L, 2, &lp);
  size_t init = start_index(luaL_optinteger(L, 3, 1), ls) - 1;
  if (init > ls) {
    luaL_pushfail(L);
    return 1;
  }
  if (find && (lua_toboolean(L, 4) || pattern_is_plain(p, lp))) {
    // memmem is linear (two-way search); Lua's own plain search is quadratic at worst.
    const void* hit = lp == 0 ? s + init : memmem(s + init, ls - init, p, lp);
    if (!hit) {
      luaL_pushfail(L);
      return 1;
    }
    lua_Integer at = static_cast<const char*>(hit) - s;
    lua_pushinteger(L, at + 1);
    lua_pushinteger(L, at + static_cast<lua_Integer>(lp));
    return 2;
  }
  Charge charge{L, find ? "string.find" : "string.match"};
  bool anchor = lp > 0 && *p == '^';
  if (anchor) {
    ++p;
    --lp;
  }
  PatternMatcher m(s, ls, p, lp, {charge_steps, &charge});
  const char* s1 = s + init;
  do {
    const char* e = m.match(s1, p);
    if (m.error()) return raise_match_error(L, m);
    if (e) {
      if (!m.settle()) return raise_match_error(L, m);
      if (!find) return push_captures(L, m, s1, e);
      lua_pushinteger(L, (s1 - s) + 1);
      lua_pushinteger(L, e - s);
      return push_captures(L, m, nullptr, nullptr) + 2;
    }
  } while (s1++ < m.subject_end() && !anchor);
  if (!m.settle()) return raise_match_error(L, m);
  luaL_pushfail(L);
  return 1;
}

int str_find(lua_State* L) { return find_or_match(L, true); }
int str_match(lua_State* L) { return find_or_match(L, false); }

// The state of a gmatch iterator, in a userdata beside the subject and pattern it points into.
struct Gmatch {
  PatternMatcher matcher;
  const char* src;
  const char* p;
  const char* last_match;
};

int gmatch_next(lua_State* L) {
  auto* g = static_cast<Gmatch*>(lua_touserdata(L, lua_upvalueindex(3)));
  Charge charge{L, "string.gmatch"};
  g->matcher.set_budget({charge_steps, &charge});
  for (const char* src = g->src; src <= g->matcher.subject_end(); ++src) {
    const char* e = g->matcher.match(src, g->p);
    if (g->matcher.error()) return raise_match_error(L, g->matcher);
    if (e && e != g->last_match) {
      g->src = g->last_match = e;
      if (!g->matcher.settle()) return raise_match_error(L, g->matcher);
      return push_captures(L, g->matcher, src, e);
    }
  }
  if (!g->matcher.settle()) return raise_match_error(L, g->matcher);
  return 0;
}

int str_gmatch(lua_State* L) {
  size_t ls, lp;
  const char* s = luaL_checklstring(L, 1, &ls);
  const char* p = luaL_checklstring(L, 2, &lp);
  size_t init = start_index(luaL_optinteger(L, 3, 1), ls) - 1;
  if (init > ls) init = ls + 1;  // past the end: the iterator finds nothing
  lua_settop(L, 2);              // the subject and pattern stay alive as the closure's upvalues
  void* memory = lua_newuserdatauv(L, sizeof(Gmatch), 0);
  new (memory) Gmatch{PatternMatcher(s, ls, p, lp, {}), s + init, p, nullptr};
  lua_pushcclosure(L, gmatch_next, 3);
  return 1;
}

// gsub with a string replacement: %0 .. %9 and %% expand.
void add_replacement_text(lua_State* L, const PatternMatcher& m, luaL_Buffer* b, const char* s,
                          const char* e) {
  size_t l;
  const char* text = lua_tolstring(L, 3, &l);
  const char* p;
  while ((p = static_cast<const char*>(std::memchr(text, '%', l))) != nullptr) {
    luaL_addlstring(b, text, static_cast<size_t>(p - text));
    ++p;  // Lua strings end in '\0': reading one past a final '%' is safe
    if (*p == '%') {
      luaL_addchar(b, *p);
    } else if (*p == '0') {
      luaL_addlstring(b, s, static_cast<size_t>(e - s));
    } else if (std::isdigit(static_cast<unsigned char>(*p))) {
      push_capture(L, m, *p - '1', s, e);
      luaL_addvalue(b);  // a position capture is a number, added as its text
    } else {
      luaL_error(L, "invalid use of '%c' in replacement string", '%');
    }
    l -= static_cast<size_t>(p + 1 - text);
    text = p + 1;
  }
  luaL_addlstring(b, text, l);
}

// Adds the replacement of match s..e; false when the original text was kept.
bool add_replacement(lua_State* L, const PatternMatcher& m, luaL_Buffer* b, const char* s,
                     const char* e, int kind) {
  if (kind == LUA_TFUNCTION) {
    lua_pushvalue(L, 3);
    int n = push_captures(L, m, s, e);
    lua_call(L, n, 1);
  } else if (kind == LUA_TTABLE) {
    push_capture(L, m, 0, s, e);
    lua_gettable(L, 3);
  } else {
    add_replacement_text(L, m, b, s, e);
    return true;
  }
  if (!lua_toboolean(L, -1)) {  // nil or false: keep the original text
    lua_pop(L, 1);
    luaL_addlstring(b, s, static_cast<size_t>(e - s));
    return false;
  }
  if (!lua_isstring(L, -1)) luaL_error(L, "invalid replacement value (a %s)", luaL_typename(L, -1));
  luaL_addvalue(b);
  return true;
}

int str_gsub(lua_State* L) {
  size_t srcl, lp;
  const char* src = luaL_checklstring(L, 1, &srcl);
  const char* p = luaL_checklstring(L, 2, &lp);
  int kind = lua_type(L, 3);
  lua_Integer max_s = luaL_optinteger(L, 4, static_cast<lua_Integer>(srcl) + 1);
  luaL_argexpected(
      L, kind == LUA_TNUMBER || kind == LUA_TSTRING || kind == LUA_TFUNCTION || kind == LUA_TTABLE,
      3, "string/function/table");
  luaL_Buffer b;
  luaL_buffinit(L, &b);
  bool anchor = lp > 0 && *p == '^';
  if (anchor) {
    ++p;
    --lp;
  }
  Charge charge{L, "string.gsub"};
  PatternMatcher m(src, srcl, p, lp, {charge_steps, &charge});
  const char* last_match = nullptr;
  lua_Integer n = 0;
  bool changed = false;
  while (n < max_s) {
    const char* e = m.match(src, p);
    if (m.error()) return raise_match_error(L, m);
    if (e && e != last_match) {
      ++n;
      changed = add_replacement(L, m, &b, src, e, kind) || changed;
      src = last_match = e;
    } else if (src < m.subject_end()) {
      luaL_addchar(&b, *src++);
    } else {
      break;
    }
    if (anchor) break;
  }
  if (!m.settle()) return raise_match_error(L, m);
  if (!changed) {
    lua_pushvalue(L, 1);
  } else {
    luaL_addlstring(&b, src, static_cast<size_t>(m.subject_end() - src));
    luaL_pushresult(&b);
  }
  lua_pushinteger(L, n);
  return 2;
}

// string.rep: Lua 5.4 copies an empty string n times in a loop (string.rep("", 1 << 60) never
// returns). Any other result holds at least n bytes, so the memory cap bounds Lua's own loop.
int str_rep(lua_State* L) {
  size_t l = 0, lsep = 0;
  luaL_checklstring(L, 1, &l);
  lua_Integer n = luaL_checkinteger(L, 2);
  luaL_optlstring(L, 3, "", &lsep);
  if (n <= 0 || l + lsep == 0) {
    lua_pushliteral(L, "");
    return 1;
  }
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, 1);
  return 1;
}

// table.move(a1, f, e, t [, a2]): Lua's loop runs e - f + 1 times even over nils, which cost
// no memory; the count is charged to the library budget first.
int tab_move(lua_State* L) {
  lua_Integer f = luaL_checkinteger(L, 2);
  lua_Integer e = luaL_checkinteger(L, 3);
  if (e >= f && (f > 0 || e < LUA_MAXINTEGER + f)) {  // else Lua's own move reports the range
    if (!LuaSandbox::charge(L, e - f + 1, "table.move")) return LuaSandbox::stop(L);
  }
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

// library[name] = fn, with library's own function as fn's upvalue when `wraps`.
void replace(lua_State* L, const char* library, const char* name, lua_CFunction fn, bool wraps) {
  lua_getglobal(L, library);
  if (wraps) {
    lua_getfield(L, -1, name);
    lua_pushcclosure(L, fn, 1);
  } else {
    lua_pushcfunction(L, fn);
  }
  lua_setfield(L, -2, name);
  lua_pop(L, 1);
}

}  // namespace

void install_bounded_library(lua_State* L) {
  replace(L, LUA_STRLIBNAME, "find", str_find, false);
  replace(L, LUA_STRLIBNAME, "match", str_match, false);
  replace(L, LUA_STRLIBNAME, "gmatch", str_gmatch, false);
  replace(L, LUA_STRLIBNAME, "gsub", str_gsub, false);
  replace(L, LUA_STRLIBNAME, "rep", str_rep, true);
  replace(L, LUA_TABLIBNAME, "move", tab_move, true);
}

}  // namespace arbc
