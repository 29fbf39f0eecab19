// A sandboxed Lua state for one monitor (docs/runtime.md#the-sandbox).
//
// - Libraries: base, string, table, math, utf8, coroutine; no io, os, debug, package, and no
//   require, load, loadstring, loadfile, dofile, string.dump. print writes to the run's log.
// - Memory: a custom allocator refuses to grow the state beyond its cap; Lua then raises a
//   memory error, which the protected call reports.
// - Time: a count hook, every few hundred instructions of any coroutine, charges them to the
//   callback's instruction budget and checks its wall-clock budget and the interrupt flag. The
//   library functions whose cost the hook cannot see are bounded too (sandbox_strings.h):
//   string patterns by a step budget, string.rep and table.move by their result. Once a limit
//   is passed every further instruction raises again, so a script's own pcall cannot swallow
//   the error and keep looping (docs/reliability.md, "A stuck monitor").
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "runtime/lua_allocator.h"

struct lua_State;
struct lua_Debug;

namespace arbc {

struct SandboxLimits {
  size_t memory_bytes = 8u << 20;      // per lua_State
  long long instructions = 1'000'000;  // per callback (checked every kHookEvery instructions)
  // Per callback: steps of the string pattern functions (find, match, gmatch, gsub) and
  // elements of table.move, work a single C call does where the hook never fires.
  long long library_steps = 10'000'000;
  double wall_seconds = 0.5;  // per callback, checked with the instruction and step budgets
  // Not null: when it becomes true (a signal handler sets it), every callback stops at its next
  // check with the error "interrupted".
  const std::atomic<bool>* interrupt = nullptr;
};

inline constexpr int kHookEvery = 256;  // instructions between two checks of the limits

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
  size_t memory_used() const { return memory_.used(); }
  const SandboxLimits& limits() const { return limits_; }
  // Where print() output goes (default: stderr).
  void set_print(std::function<void(const std::string&)> print) { print_ = std::move(print); }

  // Loads and runs a chunk (text only, no bytecode) named `chunk_name` (shown in errors).
  LuaCall run_chunk(const std::string& text, const std::string& chunk_name);
  // How Lua names the last chunk run in its messages ("monitors/x.lua", or "...x.lua" when the
  // name is long): what error positions start with.
  const std::string& chunk_source() const { return chunk_source_; }

  // Calls fn(L) under lua_pcall with the instruction budget armed; fn finds `argument` as a
  // light userdata at stack index 1 and passes results back through it. fn may raise Lua
  // errors. The stack is empty afterwards.
  LuaCall protected_call(int (*fn)(lua_State*), void* argument);
  // Inside a protected call, before the next of several callbacks: fresh budgets for it.
  void rearm() { arm(); }

  // PortMonitor.novalue() (a lua_CFunction): raises the error that ends the call with
  // Status::NoValue.
  static int raise_novalue(lua_State* L);

  // For library functions that do work the instruction hook cannot see (sandbox_strings.cc):
  // charges `steps` of `function`'s work to the running callback. False when the callback must
  // stop (a budget is spent, the wall clock passed, an interrupt): then return stop(L).
  static bool charge(lua_State* L, long long steps, const char* function);
  // Ends the running callback after a limit was passed; no pcall of the script can resume it.
  static int stop(lua_State* L);

 private:
  // The limits of the callback now running, reset by arm().
  struct CallLimits {
    long long instructions_left = 0;
    long long library_steps_left = 0;
    std::chrono::steady_clock::time_point
        started;  // at the first check (cheap calls read no clock)
    bool clock_started = false;
    std::string exhausted;  // which limit stopped the callback; empty while within them
    std::string where;      // "monitors/x.lua:12": where it stopped
  };
  static void budget_hook(lua_State* L, lua_Debug* ar);
  static int print(lua_State* L);
  void arm();
  bool within_limits(lua_State* L, const char* function);
  bool exhaust(lua_State* L, std::string why);
  LuaCall finish_call(int rc);

  explicit LuaSandbox(const SandboxLimits& limits)
      : limits_(limits), memory_(limits.memory_bytes) {}
  SandboxLimits limits_;
  LuaAllocator memory_;
  lua_State* L_ = nullptr;
  int hook_every_ = kHookEvery;
  CallLimits call_;
  std::string chunk_source_;
  std::function<void(const std::string&)> print_;
};

}  // namespace arbc
