// A port monitor script in its own sandbox, with the PortMonitor API
// (docs/runtime.md#lua-monitors-the-portmonitor-api):
//
//   PortMonitor.create(options)  options = {source=, destination=, connection=}
//   PortMonitor.accept(msg) -> boolean [, reason]   PortMonitor.update(msg) -> value
//   PortMonitor.trig()                       PortMonitor.destroy()
//   PortMonitor.setEvent(name [, lifetime_s])  PortMonitor.unsetEvent(name)
//   PortMonitor.setConstraint(text)  PortMonitor.getConstraint()   (setConstraint only checks)
//   PortMonitor.setTrigInterval(s)   PortMonitor.now()   PortMonitor.hasEvent(name)
//   PortMonitor.novalue()   -- ends the callback: the message has no value (drop `no-value`)
//
// Callbacks the script does not define behave as: accept -> true, update -> msg unchanged,
// create -> true, trig/destroy -> nothing.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/instant.h"
#include "core/script_lines.h"
#include "core/type.h"
#include "core/value.h"
#include "runtime/lua_sandbox.h"

namespace arbc {

// What a monitor's PortMonitor calls act on: its connection and the destination's container.
// Times and lifetimes are the runtime's whole nanoseconds (core/instant.h); the Lua API's
// seconds are converted in lua_monitor.cc, with nanos_from_seconds.
class MonitorHost {
 public:
  virtual ~MonitorHost() = default;
  virtual Nanos now() = 0;
  // The run's clock read as ROS 2 time, what age() measures stamps against: the wall clock's
  // time since the epoch in a real-time run (Executor::stamp_origin), now() in simulation.
  virtual Nanos stamp_now() { return now(); }
  virtual void set_event(std::string_view name, std::optional<Nanos> lifetime) = 0;
  virtual void unset_event(std::string_view name) = 0;
  virtual bool has_event(std::string_view name) = 0;
  // The constraint is the model's (app.json), installed by the runtime: this only checks that
  // text is the same formula. False and *err on a syntax error or another constraint.
  virtual bool set_constraint(std::string_view text, std::string* err) = 0;
  virtual std::string get_constraint() = 0;
  virtual void set_trig_interval(Nanos interval) = 0;
  virtual void print(const std::string& line) = 0;
};

struct MonitorOptions {
  std::string source, destination, connection;
};

class LuaMonitor {
 public:
  // Creates the sandbox and runs the script's top level. On failure returns nullptr and
  // sets *error (with the file and line).
  static std::unique_ptr<LuaMonitor> load(const std::string& script, const std::string& file,
                                          const SandboxLimits& limits, MonitorHost* host,
                                          std::string* error);

  // Does the script define PortMonitor.<callback> as a function?
  bool defines(const char* callback) const;

  // Each runs one callback under the sandbox's limits. A callback returning the wrong type
  // is an error. accept() also stages msg for the following update(); when accept returns
  // `false, "reason"`, *reason receives the string.
  LuaCall create(const MonitorOptions& options, bool* created);
  LuaCall accept(const Value& msg, bool* accepted, std::string* reason = nullptr);
  LuaCall update(const Type& destination, Value* out);

  // The runtime's message path: accept, then after_accept(context, accepted) (C++ between the
  // two callbacks: the constraint and the throttle; it must not raise Lua errors), then, when
  // accept accepted, after_accept returned true and `with_update`, update, all in one
  // protected call: one set-up of the sandbox per message instead of two. Each callback has
  // its own budgets, as with accept() and update(). after_accept does not run when accept
  // failed.
  struct Passage {
    bool accepted = false;         // accept's verdict (true without an accept)
    std::string reason;            // accept's `false, "reason"`
    bool updated = false;          // update ran and *output holds its value
    Value output;                  // update's result, read as the destination's type
    const char* stage = "accept";  // the callback a failure or novalue() came from
  };
  using AfterAccept = bool (*)(void* context, bool accepted);
  LuaCall pass(const Value& msg, const Type& destination, bool with_update,
               AfterAccept after_accept, void* context, Passage* out);
  LuaCall trig();
  LuaCall destroy();

  size_t memory_used() const { return sandbox_->memory_used(); }
  const std::string& file() const { return file_; }

 private:
  struct Call;  // argument block passed through protected calls
  static int run_create(lua_State* L);
  static int run_accept(lua_State* L);
  static int run_update(lua_State* L);
  static int run_pass(lua_State* L);
  static int run_simple(lua_State* L);
  void install_api();

  // Errors on lines inlined from a user's `script` cite that file and line
  // (core/script_lines.h).
  LuaCall cited(LuaCall call) const;

  std::unique_ptr<LuaSandbox> sandbox_;
  MonitorHost* host_ = nullptr;
  std::string file_;
  std::vector<ScriptSpan> script_spans_;
  int staged_ref_ = 0;  // registry index of the message staged by accept for update
};

}  // namespace arbc
