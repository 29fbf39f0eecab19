#include "runtime/lua_sandbox.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <lua.hpp>
#include <string>

#include "core/duration_literal.h"
#include "runtime/sandbox_strings.h"

namespace arbc {

namespace {

char novalue_key;  // its address marks the no-value error object

LuaSandbox* sandbox_of(lua_State* L) { return *static_cast<LuaSandbox**>(lua_getextraspace(L)); }

// Runs a C function given as a light userdata upvalue with its argument; lets LuaSandbox
// call plain function pointers under lua_pcall.
struct Trampoline {
  int (*fn)(lua_State*);
  void* argument;
};

int trampoline(lua_State* L) {
  auto* t = static_cast<Trampoline*>(lua_touserdata(L, 1));
  lua_pushlightuserdata(L, t->argument);
  lua_replace(L, 1);
  return t->fn(L);
}

void open_library(lua_State* L, const char* name, lua_CFunction open) {
  luaL_requiref(L, name, open, 1);
  lua_pop(L, 1);
}

void remove_global(lua_State* L, const char* name) {
  lua_pushnil(L);
  lua_setglobal(L, name);
}

int open_libraries(lua_State* L) {
  open_library(L, LUA_GNAME, luaopen_base);
  open_library(L, LUA_STRLIBNAME, luaopen_string);
  open_library(L, LUA_TABLIBNAME, luaopen_table);
  open_library(L, LUA_MATHLIBNAME, luaopen_math);
  open_library(L, LUA_UTF8LIBNAME, luaopen_utf8);
  open_library(L, LUA_COLIBNAME, luaopen_coroutine);
  for (const char* name :
       {"load", "loadstring", "loadfile", "dofile", "require", "io", "os", "debug", "package"}) {
    remove_global(L, name);
  }
  lua_getglobal(L, LUA_STRLIBNAME);
  lua_pushnil(L);
  lua_setfield(L, -2, "dump");
  lua_pop(L, 1);
  install_bounded_library(L);
  // luaL_requiref registered the libraries in package.loaded; drop that table too.
  lua_pushnil(L);
  lua_setfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
  return 0;
}

}  // namespace

void LuaSandbox::budget_hook(lua_State* L, lua_Debug*) {
  LuaSandbox* self = sandbox_of(L);
  int every = lua_gethookcount(L);
  self->call_.instructions_left -= every;
  if (self->call_.exhausted.empty() && self->within_limits(L, nullptr)) {
    // A coroutine left firing on every instruction by an earlier callback's stop: back to normal.
    if (every != self->hook_every_) lua_sethook(L, budget_hook, LUA_MASKCOUNT, self->hook_every_);
    return;
  }
  stop(L);
}

// file:line of the innermost Lua function on the stack (a C function has no line).
static std::string innermost_position(lua_State* L) {
  lua_Debug ar;
  for (int level = 0; lua_getstack(L, level, &ar); ++level) {
    if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0)
      return std::string(ar.short_src) + ":" + std::to_string(ar.currentline);
  }
  return "";
}

bool LuaSandbox::exhaust(lua_State* L, std::string why) {
  call_.exhausted = std::move(why);
  call_.where = innermost_position(L);
  return false;
}

bool LuaSandbox::within_limits(lua_State* L, const char* function) {
  if (limits_.interrupt && limits_.interrupt->load(std::memory_order_relaxed))
    return exhaust(L, "interrupted");
  if (call_.instructions_left <= 0) {
    return exhaust(L, "instruction budget of " + std::to_string(limits_.instructions) +
                          " exceeded (an endless loop?)");
  }
  if (call_.library_steps_left <= 0) {
    std::string name = function ? function : "a library function";
    bool pattern = name.rfind("string.", 0) == 0;
    return exhaust(L, name + ": work budget of " + std::to_string(limits_.library_steps) +
                          " steps exceeded" +
                          (pattern ? " (a pattern that backtracks without end? Lua patterns "
                                     "retry every split of a run of optional items)"
                                   : ""));
  }
  auto now = std::chrono::steady_clock::now();
  if (!call_.clock_started) {
    call_.started = now;
    call_.clock_started = true;
  } else if (std::chrono::duration<double>(now - call_.started).count() > limits_.wall_seconds) {
    return exhaust(L,
                   "wall-clock budget of " + duration_literal(limits_.wall_seconds) + " exceeded");
  }
  return true;
}

bool LuaSandbox::charge(lua_State* L, long long steps, const char* function) {
  LuaSandbox* self = sandbox_of(L);
  self->call_.library_steps_left -= steps;
  return self->call_.exhausted.empty() && self->within_limits(L, function);
}

int LuaSandbox::stop(lua_State* L) {
  LuaSandbox* self = sandbox_of(L);
  if (self->call_.exhausted.empty()) self->exhaust(L, "stopped");
  // From now on, fire on every instruction of this thread until the callback is left.
  lua_sethook(L, budget_hook, LUA_MASKCOUNT, 1);
  return luaL_error(L, "%s", self->call_.exhausted.c_str());
}

void LuaSandbox::arm() {
  call_.instructions_left = limits_.instructions;
  call_.library_steps_left = limits_.library_steps;
  call_.clock_started = false;
  call_.exhausted.clear();
  call_.where.clear();
  lua_sethook(L_, budget_hook, LUA_MASKCOUNT, hook_every_);
}

int LuaSandbox::print(lua_State* L) {
  // Every argument to a string on the stack first: __tostring may raise (a longjmp), which
  // would skip the destructor of a C++ line already under construction.
  int n = lua_gettop(L);
  luaL_checkstack(L, n, "too many arguments to print");
  for (int i = 1; i <= n; ++i) luaL_tolstring(L, i, nullptr);
  std::string line;
  for (int i = 1; i <= n; ++i) {
    if (i > 1) line += '\t';
    size_t len;
    const char* s = lua_tolstring(L, n + i, &len);
    line.append(s, len);
  }
  LuaSandbox* self = sandbox_of(L);
  if (self->print_) {
    self->print_(line);
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  return 0;
}

std::unique_ptr<LuaSandbox> LuaSandbox::create(const SandboxLimits& limits) {
  std::unique_ptr<LuaSandbox> box(new LuaSandbox(limits));
  box->hook_every_ = static_cast<int>(std::clamp<long long>(limits.instructions, 1, kHookEvery));
  box->L_ = lua_newstate(&LuaAllocator::allocate, &box->memory_);
  if (!box->L_) return nullptr;
  *static_cast<LuaSandbox**>(lua_getextraspace(box->L_)) = box.get();
  lua_atpanic(box->L_, [](lua_State* L) -> int {
    // Only reachable through a bug in this file (every entry is protected): fail loudly.
    std::fprintf(stderr, "arbc: unprotected Lua error: %s\n", lua_tostring(L, -1));
    std::abort();
  });
  // The generational collector keeps small monitor states small between messages.
  lua_gc(box->L_, LUA_GCGEN, 0, 0);
  lua_pushcfunction(box->L_, open_libraries);
  if (lua_pcall(box->L_, 0, 0, 0) != LUA_OK) return nullptr;
  lua_pushcfunction(box->L_, [](lua_State* L) -> int {
    lua_pushcfunction(L, &LuaSandbox::print);
    lua_setglobal(L, "print");
    return 0;
  });
  if (lua_pcall(box->L_, 0, 0, 0) != LUA_OK) return nullptr;
  return box;
}

LuaSandbox::~LuaSandbox() {
  if (!L_) return;
  arm();  // finalizers (__gc) run in lua_close: a looping one is cut off like any callback
  lua_close(L_);
}

int LuaSandbox::raise_novalue(lua_State* L) {
  lua_pushlightuserdata(L, &novalue_key);
  return lua_error(L);
}

LuaCall LuaSandbox::finish_call(int rc) {
  lua_sethook(L_, nullptr, 0, 0);
  LuaCall call;
  if (rc == LUA_OK && call_.exhausted.empty()) return call;
  call.status = LuaCall::Status::Error;
  if (!call_.exhausted.empty()) {
    call.error = (call_.where.empty() ? std::string("?") : call_.where) + ": " + call_.exhausted;
  } else if (rc == LUA_ERRMEM) {
    call.error = "memory cap of " + std::to_string(limits_.memory_bytes / 1024) + " KiB exceeded";
  } else if (lua_islightuserdata(L_, -1) && lua_touserdata(L_, -1) == &novalue_key) {
    call.status = LuaCall::Status::NoValue;
  } else if (lua_type(L_, -1) == LUA_TSTRING) {
    call.error = lua_tostring(L_, -1);
  } else {
    call.error = std::string("error object is a ") + luaL_typename(L_, -1) + " value";
  }
  lua_settop(L_, 0);
  // A failed allocation leaves garbage; collect it now rather than on the next message.
  if (rc == LUA_ERRMEM) lua_gc(L_, LUA_GCCOLLECT);
  return call;
}

LuaCall LuaSandbox::run_chunk(const std::string& text, const std::string& chunk_name) {
  std::string name = "@" + chunk_name;
  int rc = luaL_loadbufferx(L_, text.data(), text.size(), name.c_str(), "t");
  if (rc != LUA_OK) {
    call_.exhausted.clear();
    return finish_call(rc);
  }
  lua_Debug chunk;
  lua_pushvalue(L_, -1);
  if (lua_getinfo(L_, ">S", &chunk)) chunk_source_ = chunk.short_src;  // pops the copy
  arm();
  return finish_call(lua_pcall(L_, 0, 0, 0));
}

LuaCall LuaSandbox::protected_call(int (*fn)(lua_State*), void* argument) {
  Trampoline t{fn, argument};
  lua_settop(L_, 0);
  lua_pushcfunction(L_, trampoline);
  lua_pushlightuserdata(L_, &t);
  arm();
  int rc = lua_pcall(L_, 1, LUA_MULTRET, 0);
  if (rc != LUA_OK || !call_.exhausted.empty()) return finish_call(rc);
  lua_sethook(L_, nullptr, 0, 0);
  lua_settop(L_, 0);
  return LuaCall{};
}

}  // namespace arbc
