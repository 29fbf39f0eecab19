#include "runtime/lua_monitor.h"

#include <lua.hpp>

#include "runtime/lua_value.h"

namespace arbc {

namespace {

MonitorHost* host_of(lua_State* L) {
  return static_cast<MonitorHost*>(lua_touserdata(L, lua_upvalueindex(1)));
}

// Lua's seconds to the runtime's nanoseconds: the nearest one (core/instant.h), so a lifetime
// of 0.1 is 100 ms exactly and two times that round to the same nanosecond are one instant.
int api_set_event(lua_State* L) {
  const char* name = luaL_checkstring(L, 1);
  std::optional<Nanos> lifetime;
  if (!lua_isnoneornil(L, 2)) {
    double s = luaL_checknumber(L, 2);
    if (!(s >= 0)) return luaL_error(L, "setEvent: lifetime must be >= 0 seconds, got %f", s);
    lifetime = nanos_from_seconds(s);
  }
  host_of(L)->set_event(name, lifetime);
  return 0;
}

int api_unset_event(lua_State* L) {
  host_of(L)->unset_event(luaL_checkstring(L, 1));
  return 0;
}

int api_has_event(lua_State* L) {
  lua_pushboolean(L, host_of(L)->has_event(luaL_checkstring(L, 1)));
  return 1;
}

// Lua raises errors with longjmp, which skips C++ destructors: a C++ object alive when the
// API function raises (an error it reports, or a memory error at the state's cap while pushing
// a string) would leak. So the API functions below raise only when no C++ object is alive,
// and push C++ strings through a protected call.

int push_string_unprotected(lua_State* L) {
  const auto* text = static_cast<const std::string*>(lua_touserdata(L, 1));
  lua_pushlstring(L, text->data(), text->size());
  return 1;
}

// Pushes text; on a memory error pushes the error object instead and returns false.
bool push_string(lua_State* L, const std::string& text) {
  lua_pushcfunction(L, push_string_unprotected);
  lua_pushlightuserdata(L, const_cast<std::string*>(&text));
  return lua_pcall(L, 1, 1, 0) == LUA_OK;
}

int api_set_constraint(lua_State* L) {
  const char* text = luaL_checkstring(L, 1);
  bool pushed = false;
  {
    std::string error;
    if (host_of(L)->set_constraint(text, &error)) return 0;
    pushed = push_string(L, "setConstraint: " + error);  // else a memory error was pushed
  }
  if (pushed) {  // prefix the script's file and line, as luaL_error does
    luaL_where(L, 1);
    lua_insert(L, -2);
    lua_concat(L, 2);
  }
  return lua_error(L);
}

int api_get_constraint(lua_State* L) {
  bool pushed = false;
  {
    std::string text = host_of(L)->get_constraint();
    pushed = push_string(L, text);
  }
  return pushed ? 1 : lua_error(L);
}

int api_set_trig_interval(lua_State* L) {
  double s = luaL_checknumber(L, 1);
  // Under half a nanosecond would be no interval at all: trig again and again at one instant.
  Nanos interval = nanos_from_seconds(s);
  if (!(interval > Nanos(0)))
    return luaL_error(L, "setTrigInterval: interval must be at least 0.000000001 seconds (1 ns)");
  host_of(L)->set_trig_interval(interval);
  return 0;
}

int api_now(lua_State* L) {
  lua_pushnumber(L, seconds_of(host_of(L)->now()));
  return 1;
}

int api_stamp_now(lua_State* L) {
  lua_pushnumber(L, seconds_of(host_of(L)->stamp_now()));
  return 1;
}

// What install_host_api() needs and returns.
struct Install {
  MonitorHost* host = nullptr;
  int staged_ref = LUA_NOREF;  // out: the registry slot of the message between accept and update
};

int install_host_api(lua_State* L) {
  auto* in = static_cast<Install*>(lua_touserdata(L, 1));
  void* host = in->host;
  static const luaL_Reg api[] = {
      {"setEvent", api_set_event},
      {"unsetEvent", api_unset_event},
      {"hasEvent", api_has_event},
      {"setConstraint", api_set_constraint},
      {"getConstraint", api_get_constraint},
      {"setTrigInterval", api_set_trig_interval},
      {"now", api_now},
      {"stamp_now", api_stamp_now},
      {"novalue", LuaSandbox::raise_novalue},
      {nullptr, nullptr},
  };
  lua_newtable(L);
  lua_pushlightuserdata(L, host);
  luaL_setfuncs(L, api, 1);
  lua_setglobal(L, "PortMonitor");
  prepare_lua_values(L);
  // An integer slot of the registry: a store and a load on the message path cost an array
  // access, where a light-userdata key cost a hash lookup each.
  lua_pushboolean(L, false);
  in->staged_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_pushnil(L);  // nothing staged yet, as before the first accept
  lua_rawseti(L, LUA_REGISTRYINDEX, in->staged_ref);
  return 0;
}

// Pushes PortMonitor[name]; returns whether it is a function (pushes nil otherwise).
bool push_callback(lua_State* L, const char* name) {
  if (lua_getglobal(L, "PortMonitor") != LUA_TTABLE) {
    lua_pop(L, 1);
    lua_pushnil(L);
    return false;
  }
  bool is_function = lua_getfield(L, -1, name) == LUA_TFUNCTION;
  lua_remove(L, -2);
  return is_function;
}

std::string kind_of(lua_State* L, int index) {
  return lua_isnoneornil(L, index) ? "nothing" : luaL_typename(L, index);
}

// accept's results are at -2 (the verdict) and -1 (a reason); false with call->type_error
// when the verdict is not a boolean.
bool read_verdict(lua_State* L, bool* accepted, std::string* reason, std::string* type_error) {
  if (!lua_isboolean(L, -2)) {
    *type_error = "accept must return a boolean, got " + kind_of(L, -2);
    return false;
  }
  *accepted = lua_toboolean(L, -2);
  // `return false, "no-value"`: a rejection with a reason.
  if (!*accepted && lua_type(L, -1) == LUA_TSTRING) *reason = lua_tostring(L, -1);
  return true;
}

// update's result (or the message, without an update) at -1, read as the destination's type;
// false with call->type_error when it does not fit.
bool read_output(lua_State* L, bool has_update, const Type& destination, Value* output,
                 std::string* type_error) {
  std::string why;
  auto value = read_value(L, -1, destination, &why);
  if (!value) {
    *type_error = (has_update ? "update returned a value that does not fit the destination ("
                              : "the message does not fit the destination (") +
                  why + ")";
    return false;
  }
  *output = std::move(*value);
  return true;
}

}  // namespace

struct LuaMonitor::Call {
  const char* callback = nullptr;
  const Value* message = nullptr;
  const Type* destination = nullptr;
  const MonitorOptions* options = nullptr;
  bool result = true;
  std::string reason;
  Value output;
  std::string type_error;
  int staged_ref = LUA_NOREF;
  // pass() only
  LuaSandbox* sandbox = nullptr;
  Passage* passage = nullptr;
  bool with_update = false;
  AfterAccept after_accept = nullptr;
  void* context = nullptr;
};

std::unique_ptr<LuaMonitor> LuaMonitor::load(const std::string& script, const std::string& file,
                                             const SandboxLimits& limits, MonitorHost* host,
                                             std::string* error) {
  std::unique_ptr<LuaMonitor> m(new LuaMonitor());
  m->sandbox_ = LuaSandbox::create(limits);
  if (!m->sandbox_) {
    *error = file + ": cannot create a Lua state within the memory cap";
    return nullptr;
  }
  m->host_ = host;
  m->file_ = file;
  // The sandbox's print, into the host's log.
  m->sandbox_->set_print([host](const std::string& line) { host->print(line); });
  Install in{host};
  LuaCall installed = m->sandbox_->protected_call(install_host_api, &in);
  if (!installed.ok()) {
    *error = file + ": " + installed.error;
    return nullptr;
  }
  m->staged_ref_ = in.staged_ref;
  m->script_spans_ = script_spans(script);
  LuaCall ran = m->cited(m->sandbox_->run_chunk(script, file));
  if (!ran.ok()) {
    *error = ran.status == LuaCall::Status::NoValue ? file + ": novalue() at top level" : ran.error;
    if (error->rfind(file, 0) != 0) *error = file + ": " + *error;
    return nullptr;
  }
  return m;
}

LuaCall LuaMonitor::cited(LuaCall call) const {
  // Before the chunk compiled, Lua's name for it is the file name (unless over LUA_IDSIZE).
  const std::string& chunk = sandbox_->chunk_source().empty() ? file_ : sandbox_->chunk_source();
  if (!call.error.empty()) call.error = cite_script_lines(call.error, chunk, script_spans_);
  return call;
}

// Protected: a script may have put metamethods on PortMonitor or _G that raise errors.
bool LuaMonitor::defines(const char* callback) const {
  Call call;
  call.callback = callback;
  LuaCall r = sandbox_->protected_call(
      [](lua_State* L) -> int {
        auto* c = static_cast<Call*>(lua_touserdata(L, 1));
        c->result = push_callback(L, c->callback);
        return 0;
      },
      &call);
  return r.ok() && call.result;
}

int LuaMonitor::run_create(lua_State* L) {
  auto* call = static_cast<Call*>(lua_touserdata(L, 1));
  if (!push_callback(L, "create")) return 0;
  lua_createtable(L, 0, 3);
  lua_pushstring(L, call->options->source.c_str());
  lua_setfield(L, -2, "source");
  lua_pushstring(L, call->options->destination.c_str());
  lua_setfield(L, -2, "destination");
  lua_pushstring(L, call->options->connection.c_str());
  lua_setfield(L, -2, "connection");
  lua_call(L, 1, 1);
  if (lua_isnil(L, -1)) return 0;  // a create that returns nothing accepts the connection
  if (!lua_isboolean(L, -1)) {
    call->type_error = "create must return a boolean, got " + kind_of(L, -1);
    return 0;
  }
  call->result = lua_toboolean(L, -1);
  return 0;
}

int LuaMonitor::run_accept(lua_State* L) {
  auto* call = static_cast<Call*>(lua_touserdata(L, 1));
  push_value(L, *call->message);
  lua_pushvalue(L, -1);
  lua_rawseti(L, LUA_REGISTRYINDEX, call->staged_ref);
  if (!push_callback(L, "accept")) return 0;
  lua_pushvalue(L, -2);
  lua_call(L, 1, 2);
  read_verdict(L, &call->result, &call->reason, &call->type_error);
  return 0;
}

int LuaMonitor::run_update(lua_State* L) {
  auto* call = static_cast<Call*>(lua_touserdata(L, 1));
  bool has_update = push_callback(L, "update");
  lua_rawgeti(L, LUA_REGISTRYINDEX, call->staged_ref);
  if (has_update) lua_call(L, 1, 1);
  read_output(L, has_update, *call->destination, &call->output, &call->type_error);
  return 0;
}

int LuaMonitor::run_pass(lua_State* L) {
  auto* call = static_cast<Call*>(lua_touserdata(L, 1));
  Passage* p = call->passage;
  push_value(L, *call->message);
  int msg = lua_gettop(L);
  p->accepted = true;
  if (push_callback(L, "accept")) {
    lua_pushvalue(L, msg);
    lua_call(L, 1, 2);
    if (!read_verdict(L, &p->accepted, &p->reason, &call->type_error)) return 0;
  }
  lua_settop(L, msg);
  if (!call->after_accept(call->context, p->accepted) || !p->accepted || !call->with_update) {
    return 0;
  }
  p->stage = "update";
  call->sandbox->rearm();
  bool has_update = push_callback(L, "update");
  lua_pushvalue(L, msg);
  if (has_update) lua_call(L, 1, 1);
  p->updated = read_output(L, has_update, *call->destination, &p->output, &call->type_error);
  return 0;
}

int LuaMonitor::run_simple(lua_State* L) {
  auto* call = static_cast<Call*>(lua_touserdata(L, 1));
  if (!push_callback(L, call->callback)) return 0;
  lua_call(L, 0, 0);
  return 0;
}

// Wrong-type results are reported as errors at the callback's definition.
static LuaCall type_error(const std::string& file, const std::string& what) {
  LuaCall r;
  r.status = LuaCall::Status::Error;
  r.error = file + ": " + what;
  return r;
}

LuaCall LuaMonitor::create(const MonitorOptions& options, bool* created) {
  Call call;
  call.options = &options;
  LuaCall r = cited(sandbox_->protected_call(run_create, &call));
  if (r.ok() && !call.type_error.empty()) r = type_error(file_, call.type_error);
  *created = r.ok() && call.result;
  return r;
}

LuaCall LuaMonitor::accept(const Value& msg, bool* accepted, std::string* reason) {
  Call call;
  call.message = &msg;
  call.staged_ref = staged_ref_;
  LuaCall r = cited(sandbox_->protected_call(run_accept, &call));
  if (r.ok() && !call.type_error.empty()) r = type_error(file_, call.type_error);
  *accepted = r.ok() && call.result;
  if (reason) *reason = std::move(call.reason);
  return r;
}

LuaCall LuaMonitor::update(const Type& destination, Value* out) {
  Call call;
  call.destination = &destination;
  call.staged_ref = staged_ref_;
  LuaCall r = cited(sandbox_->protected_call(run_update, &call));
  if (r.ok() && !call.type_error.empty()) r = type_error(file_, call.type_error);
  if (r.ok()) *out = std::move(call.output);
  return r;
}

LuaCall LuaMonitor::pass(const Value& msg, const Type& destination, bool with_update,
                         AfterAccept after_accept, void* context, Passage* out) {
  Call call;
  call.message = &msg;
  call.destination = &destination;
  call.sandbox = sandbox_.get();
  call.passage = out;
  call.with_update = with_update;
  call.after_accept = after_accept;
  call.context = context;
  LuaCall r = cited(sandbox_->protected_call(run_pass, &call));
  if (r.ok() && !call.type_error.empty()) r = type_error(file_, call.type_error);
  return r;
}

LuaCall LuaMonitor::trig() {
  Call call;
  call.callback = "trig";
  return cited(sandbox_->protected_call(run_simple, &call));
}

LuaCall LuaMonitor::destroy() {
  Call call;
  call.callback = "destroy";
  return cited(sandbox_->protected_call(run_simple, &call));
}

}  // namespace arbc
