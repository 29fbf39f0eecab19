// Runtime figures (issue 5; docs/benchmarks.md "Runtime (issue 5)"):
//   constraint_decision  the container's present set at t + the compiled constraint
//   yarp_decision        the same decision the YARP way: substitute event values into the
//                        constraint text, luaL_loadstring + pcall, every message (baseline)
//   monitored_delivery   publish -> queue -> Lua accept + update on a small record -> deliver
//   bare_delivery        the same path with no monitor
//   monitored_delivery_checked  monitored_delivery with the runtime checks watching the run
//   lua_floor_tables     baseline of monitored_delivery: only the Lua work of one message, in a
//                        plain lua_State (no runtime, no sandbox): the record pushed as tables,
//                        accept and update called in one lua_pcall, the vec3 read back
//   lua_floor_reused     the same with the message's two tables made once and refilled: the
//                        lower bound of any table form (unsound, so not what runs)
//   lua_floor_userdata   the same with the record as a userdata whose fields are read through
//                        __index: what another message form would cost (not what runs)
//   monitor_memory       bytes of one monitor's lua_State (reported as a counter)
//
// Under callgrind (bench/figures/instructions.sh), each delivery and floor benchmark also
// counts the instructions of a window of its messages alone: see InstructionWindow.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <lua.hpp>
#include <string_view>

#include "bench/instruction_window.h"
#include "runtime/claim_watch.h"
#include "runtime/event_container.h"
#include "runtime/runtime.h"

namespace {

using namespace std::chrono_literals;

using namespace arbc;

using bench::InstructionWindow;

// The table-cleaning app's `track` guard, and its container after the feeds ran.
const char* kConstraint = "e_unreachable and e_arm_idle and e_pull_idle and not e_taken";
const char* kEvents[] = {"e_taken", "e_arm_idle", "e_pull_idle", "e_unreachable",
                         "e_face_detected"};

void BM_ConstraintDecision(benchmark::State& state) {
  EventContainer box;
  for (const char* e : kEvents) box.index().intern(e);
  box.set(box.index().find("e_arm_idle"), 0, 1'000'000'000s);
  box.set(box.index().find("e_pull_idle"), 0, 1'000'000'000s);
  box.set(box.index().find("e_unreachable"), 1, 1'000'000'000s);
  CompiledConstraint c =
      CompiledConstraint::compile(parse_constraint(kConstraint).constraint, box.index());
  // Time moves on every decision, so the container's expiry check runs each time. It is
  // computed from an integer step count rather than accumulated (t += dt): the accumulation
  // was a loop-carried chain through a general register (the out-of-line expire() call keeps
  // t out of the vector registers) that cost more than the decision itself.
  uint64_t step = 0;
  for (auto _ : state) {
    Nanos t = 1s + Nanos(static_cast<int64_t>(++step));
    bool selected = c.evaluate(box.present(t));
    benchmark::DoNotOptimize(selected);
  }
}
BENCHMARK(BM_ConstraintDecision);

// YARP's PortMonitor arbitrator, restated: for each event name, replace its occurrences in the
// constraint text with "true" or "false", then have Lua evaluate the result.
void BM_YarpDecision(benchmark::State& state) {
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  std::set<std::string> present = {"e_arm_idle", "e_pull_idle", "e_unreachable"};
  for (auto _ : state) {
    std::string text = kConstraint;
    for (const char* e : kEvents) {
      std::string name = e, value = present.count(name) ? "true" : "false";
      for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at)) {
        text.replace(at, name.size(), value);
        at += value.size();
      }
    }
    std::string chunk = "return " + text;
    bool selected = false;
    if (luaL_loadstring(L, chunk.c_str()) == LUA_OK && lua_pcall(L, 0, 1, 0) == LUA_OK) {
      selected = lua_toboolean(L, -1);
    }
    lua_settop(L, 0);
    benchmark::DoNotOptimize(selected);
  }
  lua_close(L);
}
BENCHMARK(BM_YarpDecision);

class Source : public Module {};
class Sink : public Module {
 public:
  void on_message(const std::string&, const Value& v) override {
    ++count;
    benchmark::DoNotOptimize(v);
  }
  uint64_t count = 0;
};

const char* kMonitor =
    "PortMonitor.accept = function(face)\n"
    "  return face.certainty >= 0.8\n"
    "end\n"
    "PortMonitor.update = function(face)\n"
    "  return face.pos\n"
    "end\n";

// What a proof of the face app gives a run to watch (runtime/claim_watch.h): the port's
// exclusivity, an assert over events, a spacing of `track`, a source rate and an invariant, each
// kept by the benchmark's messages (1 us apart, e_arm_idle present), so each is judged at every
// message and none stops being watched. The runtime reads none of it unless it watches.
void add_claims(model::App& app) {
  model::ArbitratedPort port;
  port.port = "HeadControl.gaze";
  port.rules = {"track"};
  model::Assertion assert_idle;
  assert_idle.rule = "track";
  assert_idle.property = Constraint::event_ref("e_arm_idle");
  port.asserts.push_back(assert_idle);
  app.arbitrated_ports.push_back(port);
  model::TemporalProperty spacing;
  spacing.kind = model::TemporalProperty::Kind::Spacing;
  spacing.port = "HeadControl.gaze";
  spacing.rule = "track";
  spacing.window = 500ns;
  app.temporal.push_back(spacing);
  app.rates.push_back({"FaceDetector.face", Nanos(1ms), {}});
  app.invariants.push_back({parse_constraint("not (e_taken and e_unreachable)").constraint, {}});
}

// One app: FaceDetector.face -> HeadControl.gaze, with or without the monitor above; with
// `watch`, every trace record is given to it (the runtime checks of `arbc run`).
std::unique_ptr<Runtime> face_app(const model::App& app, Trace::Watch watch, Registry& registry,
                                  std::string* error) {
  std::string dir = std::string(ARBC_BINARY_DIR) + "/bench_runtime_app";
  std::filesystem::create_directories(dir + "/monitors");
  std::ofstream(dir + "/monitors/track.lua") << kMonitor;
  std::ofstream(dir + "/monitors/feed.lua")
      << "PortMonitor.create = function(o) PortMonitor.setEvent('e_arm_idle') return true end\n";
  registry.add_module("FaceDetector", [] { return std::make_unique<Source>(); });
  registry.add_module("Arm", [] { return std::make_unique<Source>(); });
  registry.add_module("HeadControl", [] { return std::make_unique<Sink>(); });
  RunOptions options;
  options.trace_watch = std::move(watch);
  return Runtime::create(app, dir, options, error, registry);
}

model::App face_model(bool monitored) {
  model::App app;
  app.name = "bench";
  model::Module face{"FaceDetector", "", {}, {}};
  face.ports.push_back({"face",
                        model::Direction::Out,
                        parse_type(monitored ? "{pos: vec3, certainty: float}" : "vec3"),
                        {}});
  model::Module head{"HeadControl", "", {}, {}};
  head.ports.push_back({"gaze", model::Direction::In, parse_type("vec3"), {}});
  model::Module arm{"Arm", "", {}, {}};
  arm.ports.push_back({"status", model::Direction::Out, parse_type("list<string>"), {}});
  app.modules = {face, head, arm};
  model::Connection c;
  c.name = "track";
  c.source = "FaceDetector.face";
  c.destination = "HeadControl.gaze";
  c.constraint = parse_constraint("e_arm_idle and not e_taken").constraint;
  if (monitored) c.monitor = "monitors/track.lua";
  app.connections.push_back(c);
  // A feed whose create() sets e_arm_idle for good, so the guard holds.
  model::Connection feed;
  feed.name = "feed";
  feed.kind = model::ConnectionKind::Feed;
  feed.source = "Arm.status";
  feed.destination = "HeadControl.gaze";
  feed.constraint = Constraint::constant(false);
  feed.monitor = "monitors/feed.lua";
  app.connections.push_back(feed);
  add_claims(app);
  return app;
}

void delivery(benchmark::State& state, bool monitored, InstructionWindow& window,
              bool checked = false) {
  Registry registry;
  std::string error;
  model::App app = face_model(monitored);
  ClaimWatch claims(app);
  Trace::Watch watch;
  if (checked) watch = [&claims](const TraceLine& r, Trace& trace) { claims.watch(r, trace); };
  auto rt = face_app(app, std::move(watch), registry, &error);
  if (!rt) {
    state.SkipWithError(error.c_str());
    return;
  }
  rt->start();
  Value msg = monitored ? Value::record({{"pos", Value::vec3(0.1, 0.2, 0.9)}, {"certainty", 0.93}})
                        : Value::vec3(0.1, 0.2, 0.9);
  Nanos t{0};
  uint64_t messages = 0;
  for (auto _ : state) {
    rt->publish("FaceDetector", "face", msg);
    t += 1us;
    rt->advance(t);
    window.after(++messages);
  }
  auto stats = rt->stats();
  state.counters["delivered"] = static_cast<double>(stats[0].delivered);
  state.counters["not_selected"] = static_cast<double>(stats[0].drops(DropReason::NotSelected));
  if (checked) state.counters["broken"] = static_cast<double>(claims.violations().size());
}

void BM_MonitoredDelivery(benchmark::State& state) {
  static InstructionWindow window("monitored_delivery");
  delivery(state, true, window);
}
void BM_BareDelivery(benchmark::State& state) {
  static InstructionWindow window("bare_delivery");
  delivery(state, false, window);
}
// monitored_delivery with the runtime checks on (issue 39: at most 10% on the per-message path).
void BM_MonitoredDeliveryChecked(benchmark::State& state) {
  static InstructionWindow window("monitored_delivery_checked");
  delivery(state, true, window, true);
}
BENCHMARK(BM_MonitoredDelivery);
BENCHMARK(BM_BareDelivery);
BENCHMARK(BM_MonitoredDeliveryChecked);

// --- the Lua floor under monitored_delivery ---------------------------------------------
// What the Lua side of one monitored message costs with nothing of arbc around it: the same
// script, the same record, one protected call (as LuaMonitor::pass). A plain state with Lua's own
// allocator and no hook, so the ratio monitored_delivery / lua_floor_tables is what the runtime
// adds.

struct FaceRecord {
  double pos[3];
  double certainty;
};

lua_State* floor_state() {
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  lua_newtable(L);
  lua_setglobal(L, "PortMonitor");
  if (luaL_dostring(L, kMonitor) != LUA_OK) {
    lua_close(L);
    return nullptr;
  }
  return L;
}

void push_face_tables(lua_State* L, const FaceRecord& m) {
  lua_createtable(L, 0, 2);
  lua_createtable(L, 0, 3);
  const char* names[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    lua_pushnumber(L, m.pos[k]);
    lua_setfield(L, -2, names[k]);
  }
  lua_setfield(L, -2, "pos");
  lua_pushnumber(L, m.certainty);
  lua_setfield(L, -2, "certainty");
}

// The same two tables made once per state and refilled for every message: what reusing them
// would cost. Not sound (a monitor that keeps its message would see it change), so not what
// runs: the lower bound of any form in which monitors see messages as tables.
char reused_face_key;
void push_face_reused(lua_State* L, const FaceRecord& m) {
  if (lua_rawgetp(L, LUA_REGISTRYINDEX, &reused_face_key) != LUA_TTABLE) {
    lua_pop(L, 1);
    push_face_tables(L, m);
    lua_pushvalue(L, -1);
    lua_rawsetp(L, LUA_REGISTRYINDEX, &reused_face_key);
    return;
  }
  lua_getfield(L, -1, "pos");
  const char* names[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    lua_pushnumber(L, m.pos[k]);
    lua_setfield(L, -2, names[k]);
  }
  lua_pop(L, 1);
  lua_pushnumber(L, m.certainty);
  lua_setfield(L, -2, "certainty");
}

double read_vec3_table(lua_State* L) {
  double sum = 0;
  for (const char* name : {"x", "y", "z"}) {
    lua_getfield(L, -1, name);
    sum += lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  return sum;
}

int vec3_view_index(lua_State* L) {
  const auto* v = static_cast<const double*>(lua_touserdata(L, 1));
  size_t n = 0;
  const char* key = lua_tolstring(L, 2, &n);
  if (n == 1 && key[0] >= 'x' && key[0] <= 'z') {
    lua_pushnumber(L, v[key[0] - 'x']);
  } else {
    lua_pushnil(L);
  }
  return 1;
}

int face_view_index(lua_State* L) {
  const auto* m = static_cast<const FaceRecord*>(lua_touserdata(L, 1));
  std::string_view key = lua_tostring(L, 2);
  if (key == "certainty") {
    lua_pushnumber(L, m->certainty);
  } else if (key == "pos") {
    auto* v = static_cast<double*>(lua_newuserdatauv(L, sizeof m->pos, 0));
    std::copy(m->pos, m->pos + 3, v);
    luaL_setmetatable(L, "arbc_bench_vec3");
  } else {
    lua_pushnil(L);
  }
  return 1;
}

void push_face_userdata(lua_State* L, const FaceRecord& m) {
  *static_cast<FaceRecord*>(lua_newuserdatauv(L, sizeof m, 0)) = m;
  luaL_setmetatable(L, "arbc_bench_face");
}

double read_vec3_userdata(lua_State* L) {
  const auto* v = static_cast<const double*>(luaL_testudata(L, -1, "arbc_bench_vec3"));
  return v ? v[0] + v[1] + v[2] : 0;
}

// PortMonitor[callback](message at `msg`), as the runtime calls it; leaves one result.
void call_callback(lua_State* L, const char* callback, int msg) {
  lua_getglobal(L, "PortMonitor");
  lua_getfield(L, -1, callback);
  lua_remove(L, -2);
  lua_pushvalue(L, msg);
  lua_call(L, 1, 1);
}

// One message's Lua work in one protected call, as the runtime does it (LuaMonitor::pass):
// push the message, accept, update, read the result back.
template <class Push, class Read>
struct FloorMessage {
  Push push;
  Read read;
  FaceRecord message;
  double sum = 0;
  uint64_t delivered = 0;

  static int run(lua_State* L) {
    auto* self = static_cast<FloorMessage*>(lua_touserdata(L, 1));
    self->push(L, self->message);
    int msg = lua_gettop(L);
    call_callback(L, "accept", msg);
    if (!lua_toboolean(L, -1)) return 0;
    call_callback(L, "update", msg);
    self->sum += self->read(L);
    ++self->delivered;
    return 0;
  }
};

template <class Push, class Read>
void lua_floor(benchmark::State& state, Push push, Read read, InstructionWindow& window) {
  lua_State* L = floor_state();
  if (!L) {
    state.SkipWithError("the monitor script did not load");
    return;
  }
  luaL_newmetatable(L, "arbc_bench_vec3");
  lua_pushcfunction(L, vec3_view_index);
  lua_setfield(L, -2, "__index");
  luaL_newmetatable(L, "arbc_bench_face");
  lua_pushcfunction(L, face_view_index);
  lua_setfield(L, -2, "__index");
  lua_settop(L, 0);
  FloorMessage<Push, Read> one{push, read, {{0.1, 0.2, 0.9}, 0.93}};
  uint64_t messages = 0;
  for (auto _ : state) {
    lua_pushcfunction(L, (FloorMessage<Push, Read>::run));
    lua_pushlightuserdata(L, &one);
    lua_pcall(L, 1, 0, 0);
    lua_settop(L, 0);
    window.after(++messages);
  }
  benchmark::DoNotOptimize(one.sum);
  state.counters["delivered"] = static_cast<double>(one.delivered);
  lua_close(L);
}

void BM_LuaFloorTables(benchmark::State& state) {
  static InstructionWindow window("lua_floor_tables");
  lua_floor(state, push_face_tables, read_vec3_table, window);
}
void BM_LuaFloorReused(benchmark::State& state) {
  static InstructionWindow window("lua_floor_reused");
  lua_floor(state, push_face_reused, read_vec3_table, window);
}
void BM_LuaFloorUserdata(benchmark::State& state) {
  static InstructionWindow window("lua_floor_userdata");
  lua_floor(state, push_face_userdata, read_vec3_userdata, window);
}
BENCHMARK(BM_LuaFloorTables);
BENCHMARK(BM_LuaFloorReused);
BENCHMARK(BM_LuaFloorUserdata);

void BM_MonitorMemory(benchmark::State& state) {
  Registry registry;
  std::string error;
  model::App app = face_model(true);
  auto rt = face_app(app, nullptr, registry, &error);
  if (!rt) {
    state.SkipWithError(error.c_str());
    return;
  }
  rt->start();
  for (auto _ : state) {
    rt->publish("FaceDetector", "face",
                Value::record({{"pos", Value::vec3(0.1, 0.2, 0.9)}, {"certainty", 0.93}}));
    rt->advance(rt->now() + 10ms);
  }
  state.counters["bytes"] = static_cast<double>(rt->monitor_memory().at("track"));
}
BENCHMARK(BM_MonitorMemory)->Iterations(1000);

}  // namespace

BENCHMARK_MAIN();
