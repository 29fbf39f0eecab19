// A sandboxed Lua state for one monitor (docs/runtime.md#the-sandbox).
//
// - Libraries: base, string, table, math, utf8, coroutine; no io, os, debug, package, and no
//   require, load, loadstring, loadfile, dofile, string.dump. print writes to the run's log.
// - Memory: a custom allocator refuses to grow the state beyond its cap; Lua then raises a
//   memory error, which the protected call reports.
// - Time: a count hook raises an error once a callback has run its instruction budget. After
//   that every further instruction raises again, so a script's own pcall cannot swallow the
//   error and keep looping.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

struct lua_State;
struct lua_Debug;

namespace arbc {

struct SandboxLimits {
  size_t memory_bytes = 8u << 20;      // per lua_State
  long long instructions = 1'000'000;  // per callback (checked every instruction batch)
};

// The outcome of one protected call into a script.
struct LuaCall {
  enum class Status { Ok, NoValue, Error };
  Status status = Status::Ok;
  std::string error;  // "monitors/take.lua:12: attempt to index a nil value"
  bool ok() const { return status == Status::Ok; }
};

class LuaSandbox {
 public:
  // Creates the state; nullptr only when even the bare state does not fit the memory cap.
  static std::unique_ptr<LuaSandbox> create(const SandboxLimits& limits);
  ~LuaSandbox();
  LuaSandbox(const LuaSandbox&) = delete;
  LuaSandbox& operator=(const LuaSandbox&) = delete;

  lua_State* state() const { return L_; }
  size_t memory_used() const { return memory_.used; }
  const SandboxLimits& limits() const { return limits_; }
  // Where print() output goes (default: stderr).
  void set_print(std::function<void(const std::string&)> print) { print_ = std::move(print); }

  // Loads and runs a chunk (text only, no bytecode) named `chunk_name` (shown in errors).
  LuaCall run_chunk(const std::string& text, const std::string& chunk_name);

  // Calls fn(L) under lua_pcall with the instruction budget armed; fn finds `argument` as a
  // light userdata at stack index 1 and passes results back through it. fn may raise Lua
  // errors. The stack is empty afterwards.
  LuaCall protected_call(int (*fn)(lua_State*), void* argument);

  // The error raised by PortMonitor.novalue(): the call ends with Status::NoValue.
  static void push_novalue_marker(lua_State* L);

 private:
  struct Memory {
    size_t used = 0;
    size_t cap = 0;
  };
  static void* allocate(void* ud, void* ptr, size_t old_size, size_t new_size);
  static void budget_hook(lua_State* L, lua_Debug* ar);
  static int print(lua_State* L);
  LuaCall finish_call(int rc);

  explicit LuaSandbox(const SandboxLimits& limits) : limits_(limits) {}
  SandboxLimits limits_;
  Memory memory_;
  lua_State* L_ = nullptr;
  bool budget_exhausted_ = false;
  std::string budget_where_;
  std::function<void(const std::string&)> print_;
};

}  // namespace arbc
