// Test support: runs a generated monitor in a real Lua 5.4 state with a small recording
// PortMonitor table (docs/runtime.md), until tests switch to the runtime's own implementation.
// Several monitors may share one PortContainer, as the connections into one arbitrated port
// share its event container. As in the runtime, the connection's constraint, throttle,
// activity event and the events' lifetimes come from the model (use_model), not the monitor.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"

struct lua_State;

namespace arbc::codegen::testing {

// One arbitrated port's event container with a virtual clock.
class PortContainer {
 public:
  void set_time(double t) { now_ = t; }
  double now() const { return now_; }
  void set(const std::string& event, const std::string& owner, std::optional<double> life);
  void unset(const std::string& event, const std::string& owner);
  bool has(const std::string& event) const;  // some owner's entry has not expired
  std::vector<std::string> present() const;  // sorted

 private:
  struct Entry {
    std::optional<double> expiry;
  };
  std::map<std::string, std::map<std::string, Entry>> entries_;  // event -> owner -> entry
  double now_ = 0;
};

// What one accept/update call returned.
struct CallResult {
  bool ok = false;        // the callback ran without a Lua error
  std::string error;      // the Lua error message when !ok
  bool accepted = false;  // accept's result (it must be a boolean)
  // Why not delivered: "no-value" (PortMonitor.novalue()), and from deliver() also
  // "rejected", "not-selected", "throttled".
  std::string reason;
  std::string value;  // update's result, serialised by `serialise_top`
};

class LuaMonitorHarness {
 public:
  // Loads `source` (a monitor's text) named `chunk_name` into a fresh state whose PortMonitor
  // writes into `container` as `owner`. Check `load_error()` before use.
  LuaMonitorHarness(const std::string& source, const std::string& chunk_name,
                    PortContainer* container, std::string owner);
  ~LuaMonitorHarness();
  LuaMonitorHarness(const LuaMonitorHarness&) = delete;
  LuaMonitorHarness& operator=(const LuaMonitorHarness&) = delete;

  const std::string& load_error() const { return load_error_; }

  CallResult create();
  // `message_lua` is a Lua expression giving the message, e.g. "{ \"e_taken\" }".
  CallResult accept(const std::string& message_lua);
  CallResult update(const std::string& message_lua);
  CallResult trig();
  // The runtime's message path (docs/runtime.md): accept, the constraint on the container, the
  // throttle (counting deliveries only), update, then the activity event on delivery. `value`
  // is the delivered value.
  CallResult deliver(const std::string& message_lua);
  // What the runtime reads from app.json for connection `c` of `app`: its constraint, throttle
  // and activity event, and every event's lifetime (setEvent without one gets it).
  void use_model(const model::App& app, const model::Connection& c);

  const std::string& constraint() const { return constraint_; }  // the model's
  std::optional<double> trig_interval() const { return trig_interval_; }
  // Every setEvent/unsetEvent call, as "set e 0.5", "set e", "unset e".
  const std::vector<std::string>& calls() const { return calls_; }
  void clear_calls() { calls_.clear(); }
  bool has_callback(const std::string& name);

  // Deterministic text of a Lua value: tables with sorted keys, floats with %.17g and a
  // ".0" when integral, so that 1.0 and 1 read apart.
  static std::string serialise(lua_State* L, int index);

 private:
  friend struct HarnessAccess;
  CallResult call(const char* callback, const std::string& message_lua, bool want_value);

  lua_State* L_ = nullptr;
  PortContainer* container_;
  std::string owner_;
  std::string load_error_;
  std::string constraint_;
  std::optional<double> trig_interval_;
  std::optional<double> throttle_;
  std::string activity_;
  std::map<std::string, std::optional<double>> lifetimes_;
  std::optional<double> last_delivery_;
  std::vector<std::string> calls_;
};

}  // namespace arbc::codegen::testing
