#include "compiler/codegen/testing/lua_monitor_harness.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <lua.hpp>

#include "core/constraint.h"

namespace arbc::codegen::testing {

void PortContainer::set(const std::string& event, const std::string& owner,
                        std::optional<double> life) {
  Entry e;
  if (life) e.expiry = now_ + *life;
  entries_[event][owner] = e;
}

void PortContainer::unset(const std::string& event, const std::string& owner) {
  auto it = entries_.find(event);
  if (it != entries_.end()) it->second.erase(owner);
}

bool PortContainer::has(const std::string& event) const {
  auto it = entries_.find(event);
  if (it == entries_.end()) return false;
  for (const auto& [owner, entry] : it->second)
    if (!entry.expiry || now_ < *entry.expiry) return true;
  return false;
}

std::vector<std::string> PortContainer::present() const {
  std::vector<std::string> out;
  for (const auto& [event, owners] : entries_)
    if (has(event)) out.push_back(event);
  return out;
}

struct HarnessAccess {
  static LuaMonitorHarness* self(lua_State* L) {
    return static_cast<LuaMonitorHarness*>(lua_touserdata(L, lua_upvalueindex(1)));
  }
  static int set_event(lua_State* L) {
    LuaMonitorHarness* h = self(L);
    std::string name = luaL_checkstring(L, 1);
    std::optional<double> life;
    if (!lua_isnoneornil(L, 2)) life = luaL_checknumber(L, 2);
    char buf[64] = "";
    if (life) std::snprintf(buf, sizeof buf, " %g", *life);
    h->calls_.push_back("set " + name + buf);
    if (!life) {  // the event's lifetime in app.json, as the runtime applies it
      auto it = h->lifetimes_.find(name);
      if (it != h->lifetimes_.end()) life = it->second;
    }
    h->container_->set(name, h->owner_, life);
    return 0;
  }
  static int unset_event(lua_State* L) {
    LuaMonitorHarness* h = self(L);
    std::string name = luaL_checkstring(L, 1);
    h->calls_.push_back("unset " + name);
    h->container_->unset(name, h->owner_);
    return 0;
  }
  static int has_event(lua_State* L) {
    lua_pushboolean(L, self(L)->container_->has(luaL_checkstring(L, 1)));
    return 1;
  }
  // Only checks, as the runtime does: the constraint is the model's.
  static int set_constraint(lua_State* L) {
    const char* text = luaL_checkstring(L, 1);
    bool same = false;
    {  // no C++ object may be alive when lua_error longjmps
      std::string error;
      std::optional<Constraint> parsed = parse_constraint(text, &error);
      same = parsed && parsed->to_string() == self(L)->constraint_;
    }
    if (!same) return luaL_error(L, "setConstraint: not the model's constraint");
    return 0;
  }
  static int get_constraint(lua_State* L) {
    lua_pushstring(L, self(L)->constraint_.c_str());
    return 1;
  }
  static int set_trig_interval(lua_State* L) {
    self(L)->trig_interval_ = luaL_checknumber(L, 1);
    return 0;
  }
  // Ends the callback with a distinguished error object, as the runtime's does.
  static int novalue(lua_State* L) {
    lua_pushlightuserdata(L, &novalue_marker);
    return lua_error(L);
  }
  static inline int novalue_marker = 0;
  static int now(lua_State* L) {
    lua_pushnumber(L, self(L)->container_->now());
    return 1;
  }
};

LuaMonitorHarness::LuaMonitorHarness(const std::string& source, const std::string& chunk_name,
                                     PortContainer* container, std::string owner)
    : container_(container), owner_(std::move(owner)) {
  L_ = luaL_newstate();
  // The libraries the runtime's sandbox keeps (no io, os, debug, package, load*).
  luaL_requiref(L_, "_G", luaopen_base, 1);
  luaL_requiref(L_, "math", luaopen_math, 1);
  luaL_requiref(L_, "string", luaopen_string, 1);
  luaL_requiref(L_, "table", luaopen_table, 1);
  luaL_requiref(L_, "utf8", luaopen_utf8, 1);
  lua_settop(L_, 0);
  for (const char* name : {"dofile", "loadfile", "load", "require"}) {
    lua_pushnil(L_);
    lua_setglobal(L_, name);
  }
  lua_newtable(L_);
  const luaL_Reg api[] = {{"setEvent", HarnessAccess::set_event},
                          {"unsetEvent", HarnessAccess::unset_event},
                          {"hasEvent", HarnessAccess::has_event},
                          {"setConstraint", HarnessAccess::set_constraint},
                          {"getConstraint", HarnessAccess::get_constraint},
                          {"setTrigInterval", HarnessAccess::set_trig_interval},
                          {"now", HarnessAccess::now},
                          {"stamp_now", HarnessAccess::now},  // simulated: its own ROS 2 time
                          {"novalue", HarnessAccess::novalue},
                          {nullptr, nullptr}};
  lua_pushlightuserdata(L_, this);
  luaL_setfuncs(L_, api, 1);
  lua_setglobal(L_, "PortMonitor");
  if (luaL_loadbuffer(L_, source.data(), source.size(), ("@" + chunk_name).c_str()) != LUA_OK ||
      lua_pcall(L_, 0, 0, 0) != LUA_OK) {
    load_error_ = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "error";
    lua_pop(L_, 1);
  }
}

LuaMonitorHarness::~LuaMonitorHarness() { lua_close(L_); }

bool LuaMonitorHarness::has_callback(const std::string& name) {
  lua_getglobal(L_, "PortMonitor");
  lua_getfield(L_, -1, name.c_str());
  bool is_function = lua_isfunction(L_, -1);
  lua_pop(L_, 2);
  return is_function;
}

std::string LuaMonitorHarness::serialise(lua_State* L, int index) {
  index = lua_absindex(L, index);
  switch (lua_type(L, index)) {
    case LUA_TNIL:
      return "nil";
    case LUA_TBOOLEAN:
      return lua_toboolean(L, index) ? "true" : "false";
    case LUA_TNUMBER: {
      char buf[64];
      if (lua_isinteger(L, index))
        std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(lua_tointeger(L, index)));
      else
        std::snprintf(buf, sizeof buf, "%.17g", lua_tonumber(L, index));
      // A float keeps a mark of its subtype (docs/design.md#numbers-at-run-time): 1.0, not 1.
      if (!lua_isinteger(L, index) && !std::strpbrk(buf, ".eni")) std::strcat(buf, ".0");
      return buf;
    }
    case LUA_TSTRING:
      return "\"" + std::string(lua_tostring(L, index)) + "\"";
    case LUA_TTABLE: {
      std::vector<std::pair<std::string, std::string>> items;
      lua_pushnil(L);
      while (lua_next(L, index) != 0) {
        std::string key =
            lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : "[" + serialise(L, -2) + "]";
        items.emplace_back(key, serialise(L, -1));
        lua_pop(L, 1);
      }
      std::sort(items.begin(), items.end());
      std::string out = "{";
      for (size_t i = 0; i < items.size(); ++i)
        out += (i ? ", " : "") + items[i].first + "=" + items[i].second;
      return out + "}";
    }
    default:
      return luaL_typename(L, index);
  }
}

CallResult LuaMonitorHarness::call(const char* callback, const std::string& message_lua,
                                   bool want_value) {
  CallResult r;
  lua_settop(L_, 0);
  lua_getglobal(L_, "PortMonitor");
  lua_getfield(L_, -1, callback);
  if (!lua_isfunction(L_, -1)) {
    r.ok = true;  // an absent callback means the default: accept, pass through
    r.accepted = true;
    return r;
  }
  int nargs = 0;
  if (std::string(callback) == "create") {
    lua_newtable(L_);
    lua_pushstring(L_, owner_.c_str());
    lua_setfield(L_, -2, "connection");
    nargs = 1;
  } else if (!message_lua.empty()) {
    std::string chunk = "return " + message_lua;
    if (luaL_loadstring(L_, chunk.c_str()) != LUA_OK || lua_pcall(L_, 0, 1, 0) != LUA_OK) {
      r.error = std::string("bad test message: ") + lua_tostring(L_, -1);
      return r;
    }
    nargs = 1;
  }
  if (lua_pcall(L_, nargs, 1, 0) != LUA_OK) {
    if (lua_touserdata(L_, -1) == &HarnessAccess::novalue_marker) {
      r.ok = true;
      r.reason = "no-value";
      return r;
    }
    r.error = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "error object is not a string";
    return r;
  }
  if (std::string(callback) == "accept" && !lua_isboolean(L_, -1)) {
    r.error = std::string("accept returned a ") + luaL_typename(L_, -1) + ", not a boolean";
    return r;
  }
  r.ok = true;
  r.accepted = lua_toboolean(L_, -1);
  if (want_value) r.value = serialise(L_, -1);
  lua_settop(L_, 0);
  return r;
}

CallResult LuaMonitorHarness::create() { return call("create", "", false); }
CallResult LuaMonitorHarness::accept(const std::string& m) { return call("accept", m, false); }
CallResult LuaMonitorHarness::update(const std::string& m) { return call("update", m, true); }
CallResult LuaMonitorHarness::trig() { return call("trig", "", false); }

void LuaMonitorHarness::use_model(const model::App& app, const model::Connection& c) {
  constraint_ = c.constraint.to_string();
  // The model's durations are whole nanoseconds (core/instant.h); this harness keeps seconds.
  auto seconds = [](const std::optional<Nanos>& d) {
    return d ? std::optional<double>(seconds_of(*d)) : std::nullopt;
  };
  throttle_ = seconds(c.throttle);
  activity_ = c.activity_event;
  for (const model::Event& e : app.events) lifetimes_[e.name] = seconds(e.lifetime);
}

CallResult LuaMonitorHarness::deliver(const std::string& message_lua) {
  CallResult a = accept(message_lua);
  if (!a.ok || !a.reason.empty()) return a;
  if (!a.accepted) {
    if (a.reason.empty()) a.reason = "rejected";
    return a;
  }
  std::string error;
  std::optional<Constraint> parsed =
      parse_constraint(constraint_.empty() ? "true" : constraint_, &error);
  if (!parsed) {
    a.ok = false;
    a.error = "bad constraint '" + constraint_ + "': " + error;
    return a;
  }
  std::vector<std::string> present = container_->present();
  if (!evaluate(*parsed, std::set<std::string>(present.begin(), present.end()))) {
    a.accepted = false;
    a.reason = "not-selected";
    return a;
  }
  if (throttle_ && last_delivery_ && container_->now() - *last_delivery_ < *throttle_) {
    a.accepted = false;
    a.reason = "throttled";
    return a;
  }
  CallResult u = update(message_lua);
  u.accepted = u.ok && u.reason.empty();
  if (u.accepted) {
    last_delivery_ = container_->now();
    if (!activity_.empty()) container_->set(activity_, owner_, lifetimes_[activity_]);
  }
  return u;
}

}  // namespace arbc::codegen::testing
