#include "import/yarp/script_runner.h"

#include <cstdio>
#include <lua.hpp>
#include <memory>

#include "import/yarp/yarp_stand_in.h"
#include "runtime/lua_sandbox.h"

namespace arbc::yarp {
namespace {

constexpr size_t kMaxStringSamples = 12;
constexpr size_t kMaxNumberSamples = 6;

// Where recorded calls go; reached through the PortMonitor functions' upvalue.
struct Recorder {
  std::vector<RecordedCall>* calls = nullptr;
  std::optional<std::string> constraint;
  int constraint_line = 0;
};

int caller_line(lua_State* L) {
  lua_Debug ar;
  if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "l", &ar)) return ar.currentline;
  return 0;
}

// PortMonitor.<fn>(...) as YARP 3.12 behaves, without the effects: record, return nothing.
int record(lua_State* L) {
  auto* r = static_cast<Recorder*>(lua_touserdata(L, lua_upvalueindex(1)));
  const char* fn = lua_tostring(L, lua_upvalueindex(2));
  RecordedCall c;
  c.function = fn;
  c.line = caller_line(L);
  if (c.function != "setTrigInterval") c.text = luaL_checkstring(L, 1);  // as luaL_checkstring
  int number_arg = c.function == "setTrigInterval" ? 1 : 2;
  if (lua_isnumber(L, number_arg)) c.number = lua_tonumber(L, number_arg);
  if (c.function == "setConstraint") {
    r->constraint = c.text;
    r->constraint_line = c.line;
  }
  if (r->calls) r->calls->push_back(std::move(c));
  return 0;
}

void install_port_monitor(lua_State* L, Recorder* r) {
  lua_newtable(L);
  for (const char* fn : {"setEvent", "unsetEvent", "setConstraint", "setTrigInterval"}) {
    lua_pushlightuserdata(L, r);
    lua_pushstring(L, fn);
    lua_pushcclosure(L, record, 2);
    lua_setfield(L, -2, fn);
  }
  // YARP's getConstraint pushes the text but returns 0 values: the script gets nothing.
  lua_pushcfunction(L, [](lua_State*) -> int { return 0; });
  lua_setfield(L, -2, "getConstraint");
  lua_setglobal(L, "PortMonitor");
}

struct CallArgs {
  const char* callback;
  const MonitorContext* context;
  const std::string* bottle;  // for accept
  bool result = false;
  bool defined = false;
};

// Calls PortMonitor.<callback> with the Property of `create` or a thing for `accept`.
int call_callback(lua_State* L) {
  auto* a = static_cast<CallArgs*>(lua_touserdata(L, 1));
  lua_getglobal(L, "PortMonitor");
  if (!lua_istable(L, -1)) luaL_error(L, "the script does not define a PortMonitor table");
  lua_getfield(L, -1, a->callback);
  if (!lua_isfunction(L, -1)) return 0;
  a->defined = true;
  if (a->bottle) {
    lua_getglobal(L, "__arbc_thing");
    lua_pushlstring(L, a->bottle->data(), a->bottle->size());
    lua_call(L, 1, 1);
  } else {
    lua_getglobal(L, "__arbc_options");
    lua_newtable(L);
    const MonitorContext& c = *a->context;
    for (auto [k, v] : {std::pair{"filename", &c.filename},
                        {"source", &c.source},
                        {"destination", &c.destination},
                        {"carrier", &c.carrier}}) {
      lua_pushstring(L, v->c_str());
      lua_setfield(L, -2, k);
    }
    lua_pushstring(L, "lua");
    lua_setfield(L, -2, "type");
    lua_pushinteger(L, 0);
    lua_setfield(L, -2, "sender_side");
    lua_pushinteger(L, 1);
    lua_setfield(L, -2, "receiver_side");
    lua_call(L, 1, 1);
  }
  lua_call(L, 1, 1);
  a->result = lua_toboolean(L, -1);
  return 0;
}

}  // namespace

ScriptRun run_script(const std::string& text, const std::string& chunk_name,
                     const MonitorContext& context, const std::vector<std::string>& samples) {
  ScriptRun run;
  SandboxLimits limits;
  limits.memory_bytes = 16u << 20;
  std::unique_ptr<LuaSandbox> box = LuaSandbox::create(limits);
  if (!box) {
    run.error = "cannot create a Lua state";
    return run;
  }
  box->set_print([](const std::string&) {});
  Recorder recorder;
  recorder.calls = &run.create_calls;
  install_port_monitor(box->state(), &recorder);
  LuaCall prelude = box->run_chunk(std::string(yarp_stand_in_source()), "=arbc-yarp-stand-in");
  if (!prelude.ok()) {
    run.error = "internal error in the stand-in yarp module: " + prelude.error;
    return run;
  }
  LuaCall top = box->run_chunk(text, chunk_name);
  if (!top.ok()) {
    run.error = top.error;
    return run;
  }
  run.loaded = true;
  lua_getglobal(box->state(), "__arbc_yarp_required");
  run.requires_yarp = lua_toboolean(box->state(), -1);
  lua_pop(box->state(), 1);
  CallArgs create{"create", &context, nullptr};
  LuaCall c = box->protected_call(call_callback, &create);
  if (!c.ok()) {
    run.error = c.error;
    return run;
  }
  run.created = !create.defined || create.result;
  if (!run.created) run.error = "PortMonitor.create returned a false value (or nothing)";
  run.constraint = recorder.constraint;
  run.constraint_line = recorder.constraint_line;
  for (const std::string& bottle : samples) {
    SampleRun s;
    s.bottle = bottle;
    recorder.calls = &s.calls;
    CallArgs accept{"accept", &context, &bottle};
    LuaCall a = box->protected_call(call_callback, &accept);
    if (!accept.defined && a.ok()) break;  // no accept: nothing to sample
    s.ok = a.ok();
    s.accepted = a.ok() && accept.result;
    s.error = a.error;
    run.samples.push_back(std::move(s));
  }
  return run;
}

std::vector<std::string> sample_bottles(const std::set<std::string>& strings,
                                        const std::set<double>& numbers) {
  std::vector<std::string> out{""};
  size_t n = 0;
  for (const std::string& s : strings) {
    if (n++ == kMaxStringSamples) break;
    std::string quoted = "\"";
    for (char ch : s) {
      if (ch != '"') quoted += ch;
    }
    out.push_back(quoted + "\"");
  }
  n = 0;
  for (double d : numbers) {
    if (n++ == kMaxNumberSamples) break;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", d);
    out.push_back(buf);
  }
  out.push_back("0 0 0");
  out.push_back("1 1 1");
  return out;
}

}  // namespace arbc::yarp
