// Fault injection (issue 8): one fault at a time is put into a small app with arbitration, and
// each test checks three things, not just survival:
//  1. the faulty connection's counters, exactly, by drop reason;
//  2. the healthy connections deliver exactly what they deliver without the fault (a fan-out
//     sibling of the faulty connection, and an arbitrated pair with an event feed);
//  3. every count has its trace record: each drop, delivery, error, quarantine and plugin
//     exception is a line of the trace, and arrived = delivered + drops + pending everywhere.
// sandbox_test.cc covers the sandbox's own limits and messages; message_path_test.cc the
// message path without faults.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::Sink;
using testing::TestApp;

// A module that throws from every callback it has (the module plugin fault).
class Thrower : public Module {
 public:
  void start() override {
    context().schedule(2.5, [] { throw std::runtime_error("timer failed"); });
    throw std::runtime_error("start failed");
  }
  void on_message(const std::string&, const Value& v) override {
    if (v.as_int() == 2) throw 42;  // not a std::exception
    throw std::out_of_range("no such object " + std::to_string(v.as_int()));
  }
  double tick_period() const override { return 1; }
  void tick() override { throw std::logic_error("tick failed"); }
  void stop() override { throw std::runtime_error("stop failed"); }
};

// What one run left behind.
struct FaultRun {
  std::map<std::string, ConnectionStats> stats;
  std::vector<PluginStats> plugins;
  std::vector<nlohmann::json> trace;
  std::vector<std::string> reports;
  std::string table;                    // the end-of-run table `arbc run` prints
  std::map<std::string, int> sink_got;  // deliveries Sink received, by connection

  const ConnectionStats& operator[](const std::string& c) const { return stats.at(c); }
  // Trace records of `type` (and, when given, for `connection`).
  std::vector<nlohmann::json> records(const std::string& type,
                                      const std::string& connection = "") const {
    std::vector<nlohmann::json> out;
    for (const auto& r : trace) {
      if (r["type"] != type) continue;
      if (!connection.empty() && r.value("connection", "") != connection) continue;
      out.push_back(r);
    }
    return out;
  }
};

// The fault's place in the app and what drives it.
struct Fault {
  std::string script;                    // monitor of connection "faulty" ("" = none)
  std::string source = "Src.x";          // "faulty" comes from here
  std::string destination = "Sink.f";    // and goes here
  RunOptions options;                    // limits, queue bound, quarantine
  std::function<void(Runtime&)> inject;  // extra publishing, before the run
};

// A fault in the monitor of connection "faulty".
Fault monitor(std::string script) {
  Fault f;
  f.script = std::move(script);
  return f;
}

// The app: Src.x fans out to "faulty", "plain" (a monitored connection) and "hi"; Sink.a is
// arbitrated between "hi" (whose accept sets e_hi for 0.5 s) and "lo" (selected when e_hi is
// absent). Src.x publishes 1, 2, 3 at t = 1, 2, 3; Src2.y publishes at t = 1.25, 1.75, 3.25, 4.
// Without a fault: plain 3/3, hi 3/3, lo 2 of 4 (not-selected at 1.25 and 3.25).
FaultRun run(const Fault& fault) {
  TestApp t;
  t.registry.add_module("Bad", [] { return std::make_unique<Thrower>(); });
  t.module("Src", {"out x: int"});
  t.module("Src2", {"out y: int", "out w: int"});
  t.module("Sink", {"in a: int", "in b: int", "in f: int"});
  if (fault.destination.rfind("Bad.", 0) == 0) t.module("Bad", {"in i: int"});
  t.connect("faulty", fault.source, fault.destination, "true", fault.script);
  t.connect("plain", "Src.x", "Sink.b", "true",
            "PortMonitor.update = function(m) return m + 1 end\n");
  t.connect("hi", "Src.x", "Sink.a", "e_hi",
            "PortMonitor.accept = function(m) PortMonitor.setEvent('e_hi', 0.5) return true end\n");
  t.connect("lo", "Src2.y", "Sink.a", "not e_hi");
  RunOptions options = fault.options;
  options.trace_path = t.dir + "/trace.jsonl";
  auto rt = t.start(options);
  FaultRun r;
  if (!rt) return r;
  for (int i = 1; i <= 3; ++i) TestApp::publish_at(*rt, i, "Src", "x", Value(i));
  for (double at : {1.25, 1.75, 3.25, 4.0}) TestApp::publish_at(*rt, at, "Src2", "y", Value(7));
  if (fault.inject) fault.inject(*rt);
  rt->advance(5s);
  rt->shutdown();
  for (const ConnectionStats& s : rt->stats()) r.stats[s.name] = s;
  r.plugins = rt->plugin_stats();
  r.table = rt->stats_table();
  for (const auto& g : TestApp::sink(*rt).got) ++r.sink_got[g.connection];
  r.reports = t.reports;
  std::ifstream in(options.trace_path);
  for (std::string line; std::getline(in, line);) r.trace.push_back(nlohmann::json::parse(line));
  return r;
}

uint64_t all_drops(const ConnectionStats& s) {
  uint64_t n = 0;
  for (uint64_t d : s.dropped) n += d;
  return n;
}

// The healthy connections delivered exactly what they do without a fault, and every counter
// of every connection has its trace records.
void expect_unaffected_and_accounted(const FaultRun& r) {
  ASSERT_EQ(r.stats.size(), 4u);
  for (const char* name : {"plain", "hi"}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(r[name].arrived, 3u);
    EXPECT_EQ(r[name].delivered, 3u);
    EXPECT_EQ(all_drops(r[name]), 0u);
    EXPECT_EQ(r[name].errors, 0u);
    EXPECT_EQ(r.sink_got.count(name) ? r.sink_got.at(name) : 0, 3);
  }
  EXPECT_EQ(r["lo"].arrived, 4u);
  EXPECT_EQ(r["lo"].delivered, 2u);
  EXPECT_EQ(r["lo"].drops(DropReason::NotSelected), 2u);
  EXPECT_EQ(all_drops(r["lo"]), 2u);
  EXPECT_EQ(r.sink_got.count("lo") ? r.sink_got.at("lo") : 0, 2);

  for (const auto& [name, s] : r.stats) {
    SCOPED_TRACE(name);
    EXPECT_EQ(s.arrived, s.delivered + all_drops(s) + s.pending);
    EXPECT_EQ(r.records("deliver", name).size(), s.delivered);
    std::map<std::string, uint64_t> traced;
    for (const auto& d : r.records("drop", name)) ++traced[d["reason"].get<std::string>()];
    for (int i = 0; i < kDropReasonCount; ++i) {
      const char* reason = drop_reason_name(static_cast<DropReason>(i));
      EXPECT_EQ(traced[reason], s.dropped[i]) << "drops traced as " << reason;
    }
    EXPECT_EQ(r.records("error", name).size(), s.errors);
    EXPECT_EQ(r.records("quarantine", name).size(), s.quarantined ? 1u : 0u);
  }
  uint64_t plugin_errors = 0;
  for (const PluginStats& p : r.plugins) plugin_errors += p.errors;
  EXPECT_EQ(r.records("plugin-error").size(), plugin_errors);
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

// The detail of each monitor-error drop of "faulty" contains `text`.
void expect_error_details(const FaultRun& r, const std::string& text) {
  auto drops = r.records("drop", "faulty");
  ASSERT_FALSE(drops.empty());
  for (const auto& d : drops) {
    EXPECT_NE(d.value("detail", "").find(text), std::string::npos) << d.dump();
  }
  for (const auto& e : r.records("error", "faulty")) {
    EXPECT_NE(e["message"].get<std::string>().find(text), std::string::npos) << e.dump();
  }
}

// --- a monitor error in every callback ---------------------------------------------------

TEST(FaultInjectionTest, ErrorInCreateQuarantinesOnlyThatConnection) {
  FaultRun r = run(monitor("PortMonitor.create = function(o) error('create boom') end\n"));
  expect_unaffected_and_accounted(r);
  EXPECT_TRUE(r["faulty"].quarantined);
  EXPECT_EQ(r["faulty"].errors, 1u);
  EXPECT_EQ(r["faulty"].drops(DropReason::Quarantined), 3u);
  EXPECT_EQ(r["faulty"].delivered, 0u);
  auto errors = r.records("error", "faulty");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0]["message"], "monitors/faulty.lua:1: create boom");
  EXPECT_EQ(errors[0]["t"], 0.0);
}

TEST(FaultInjectionTest, ErrorInAcceptDropsEachMessage) {
  FaultRun r =
      run(monitor("PortMonitor.accept = function(m)\n  error('accept boom ' .. m)\nend\n"));
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].arrived, 3u);
  EXPECT_EQ(r["faulty"].errors, 3u);
  EXPECT_EQ(r["faulty"].drops(DropReason::MonitorError), 3u);
  EXPECT_EQ(all_drops(r["faulty"]), 3u);
  EXPECT_FALSE(r["faulty"].quarantined);
  auto drops = r.records("drop", "faulty");
  ASSERT_EQ(drops.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(drops[i]["t"], i + 1.0);
    EXPECT_EQ(drops[i]["detail"], "monitors/faulty.lua:2: accept boom " + std::to_string(i + 1));
  }
  // Three distinct texts: three reports, each naming the callback.
  EXPECT_EQ(r.reports.size(), 3u) << joined(r.reports);
  EXPECT_NE(joined(r.reports).find("connection faulty: accept failed"), std::string::npos);
}

TEST(FaultInjectionTest, ErrorInUpdateDropsEachMessage) {
  FaultRun r = run(monitor("PortMonitor.update = function(m) error('update boom') end\n"));
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].errors, 3u);
  EXPECT_EQ(r["faulty"].drops(DropReason::MonitorError), 3u);
  EXPECT_EQ(r["faulty"].delivered, 0u);
  expect_error_details(r, "monitors/faulty.lua:1: update boom");
  EXPECT_EQ(r.reports.size(), 1u) << joined(r.reports);  // one distinct text, reported once
}

TEST(FaultInjectionTest, ErrorInTrigIsCountedAndMessagesStillFlow) {
  FaultRun r = run(
      monitor("PortMonitor.create = function(o) PortMonitor.setTrigInterval(2) return true end\n"
              "PortMonitor.trig = function() PortMonitor.setEvent(nil) end\n"));
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].errors, 2u);  // trig at t = 2 and 4
  EXPECT_EQ(r["faulty"].delivered, 3u);
  EXPECT_EQ(all_drops(r["faulty"]), 0u);
  auto errors = r.records("error", "faulty");
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0]["t"], 2.0);
  EXPECT_EQ(errors[1]["t"], 4.0);
  EXPECT_NE(errors[0]["message"].get<std::string>().find("bad argument #1 to 'setEvent'"),
            std::string::npos)
      << errors[0].dump();
}

TEST(FaultInjectionTest, ErrorInDestroyIsCountedAtShutdown) {
  FaultRun r = run(monitor("PortMonitor.destroy = function() error('destroy boom') end\n"));
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].errors, 1u);
  EXPECT_EQ(r["faulty"].delivered, 3u);
  auto errors = r.records("error", "faulty");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0]["t"], 5.0);
  EXPECT_EQ(errors[0]["message"], "monitors/faulty.lua:1: destroy boom");
}

// Misusing each PortMonitor helper (or print) is an error in the callback that called it.
// Under AddressSanitizer (scripts/sanitize.sh) this also proves that an error raised inside
// a helper leaks nothing (Lua's longjmp skips C++ destructors).
TEST(FaultInjectionTest, HelperMisuseInAcceptDropsTheMessage) {
  const std::pair<std::string, std::string> cases[] = {
      {"PortMonitor.setEvent('e', -1)", "lifetime must be >= 0"},
      {"PortMonitor.setEvent({})", "bad argument #1 to 'setEvent'"},
      {"PortMonitor.unsetEvent()", "bad argument #1 to 'unsetEvent'"},
      {"PortMonitor.hasEvent(nil)", "bad argument #1 to 'hasEvent'"},
      {"PortMonitor.setConstraint('e and (')", "setConstraint: "},
      {"PortMonitor.setTrigInterval(0)", "interval must be at least 0.000000001 seconds"},
      {"PortMonitor.setTrigInterval(0/0)", "interval must be at least 0.000000001 seconds"},
      {"PortMonitor.setTrigInterval(4e-10)", "interval must be at least 0.000000001 seconds"},
      {"print(1, setmetatable({}, {__tostring = function() error('no text') end}))", "no text"},
      {"print(setmetatable({}, {__tostring = function() while true do end end}))",
       "instruction budget"},
  };
  for (const auto& [call, message] : cases) {
    SCOPED_TRACE(call);
    FaultRun r =
        run(monitor("PortMonitor.accept = function(m)\n  " + call + "\n  return true\nend\n"));
    expect_unaffected_and_accounted(r);
    EXPECT_EQ(r["faulty"].errors, 3u);
    EXPECT_EQ(r["faulty"].drops(DropReason::MonitorError), 3u);
    EXPECT_EQ(r["faulty"].delivered, 0u);
    expect_error_details(r, "monitors/faulty.lua:2: ");
    expect_error_details(r, message);
  }
}

// print() in a monitor is the sandbox's (runtime/lua_sandbox.cc): each call is one log line
// of the connection in the trace, its arguments separated by tabs.
TEST(FaultInjectionTest, PrintInAMonitorIsALogLineOfItsConnection) {
  FaultRun r =
      run(monitor("PortMonitor.accept = function(m) print('got', m, nil) return true end\n"));
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].delivered, 3u);
  std::vector<std::string> lines;
  for (const auto& l : r.records("log"))
    if (l["from"] == "faulty") lines.push_back(l["message"].get<std::string>());
  EXPECT_EQ(lines, (std::vector<std::string>{"got\t1\tnil", "got\t2\tnil", "got\t3\tnil"}));
}

TEST(FaultInjectionTest, RepeatedErrorsQuarantineAndTheRestIsCounted) {
  Fault f = monitor("PortMonitor.accept = function(m) error('again') end\n");
  f.options.quarantine_after = 2;
  FaultRun r = run(f);
  expect_unaffected_and_accounted(r);
  EXPECT_TRUE(r["faulty"].quarantined);
  EXPECT_EQ(r["faulty"].errors, 2u);
  EXPECT_EQ(r["faulty"].drops(DropReason::MonitorError), 2u);
  EXPECT_EQ(r["faulty"].drops(DropReason::Quarantined), 1u);
  auto q = r.records("quarantine", "faulty");
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q[0]["t"], 2.0);
  EXPECT_NE(q[0]["message"].get<std::string>().find("2 failures in a row"), std::string::npos);
}

// --- the sandbox's limits ----------------------------------------------------------------

TEST(FaultInjectionTest, InfiniteLoopIsCutOffEveryTime) {
  Fault f = monitor("PortMonitor.accept = function(m)\n  while true do end\nend\n");
  f.options.limits.instructions = 200000;
  FaultRun r = run(f);
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].errors, 3u);
  EXPECT_EQ(r["faulty"].drops(DropReason::MonitorError), 3u);
  expect_error_details(r, "monitors/faulty.lua:2: instruction budget of 200000 exceeded");
}

// accept and update run in one protected call (LuaMonitor::pass), yet each has its own
// instruction budget: two loops of 65 % of the budget each pass, and a loop in update is
// update's failure, not accept's.
TEST(FaultInjectionTest, AcceptAndUpdateEachHaveTheirOwnBudget) {
  const char* busy =
      "local function spin(n) local s = 0 for i = 1, n do s = s + i end return s end\n"
      "PortMonitor.accept = function(m) spin(65000) return true end\n";
  Fault within =
      monitor(std::string(busy) + "PortMonitor.update = function(m) spin(65000) return m end\n");
  within.options.limits.instructions = 200000;  // a step of spin is 2 instructions
  FaultRun ok = run(within);
  EXPECT_EQ(ok["faulty"].delivered, 3u);
  EXPECT_EQ(ok["faulty"].errors, 0u);

  Fault endless =
      monitor(std::string(busy) + "PortMonitor.update = function(m)\n  while true do end\nend\n");
  endless.options.limits.instructions = 200000;
  FaultRun r = run(endless);
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].drops(DropReason::MonitorError), 3u);
  expect_error_details(r, "monitors/faulty.lua:4: instruction budget of 200000 exceeded");
  bool named_update = false;
  for (const std::string& line : r.reports) {
    named_update |= line.find("update failed") != std::string::npos;
  }
  EXPECT_TRUE(named_update);
}

TEST(FaultInjectionTest, MemoryBombHitsTheCapEveryTime) {
  Fault f = monitor(
      "local keep = {}\n"
      "PortMonitor.accept = function(m)\n"
      "  for i = 1, 1e9 do keep[#keep + 1] = string.rep('x', 1000) .. i end\n"
      "end\n");
  f.options.limits.memory_bytes = 2 << 20;
  FaultRun r = run(f);
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].errors, 3u);
  EXPECT_EQ(r["faulty"].drops(DropReason::MonitorError), 3u);
  expect_error_details(r, "memory cap of 2048 KiB exceeded");
}

// --- module plugin faults ----------------------------------------------------------------

TEST(FaultInjectionTest, ModuleThatThrowsFromEveryCallbackIsContained) {
  Fault f;
  f.destination = "Bad.i";
  FaultRun r = run(f);
  expect_unaffected_and_accounted(r);
  // The messages reached the module: delivered, not dropped; the module's throws are its own.
  EXPECT_EQ(r["faulty"].delivered, 3u);
  EXPECT_EQ(all_drops(r["faulty"]), 0u);
  EXPECT_EQ(r["faulty"].errors, 0u);
  uint64_t bad_errors = 0;
  for (const PluginStats& p : r.plugins) {
    if (p.name == "Bad") {
      bad_errors = p.errors;
    } else {
      EXPECT_EQ(p.errors, 0u) << p.name;
    }
  }
  // start 1 + on_delivery 3 + tick at t = 1..5 + timer 1 + stop 1.
  EXPECT_EQ(bad_errors, 11u);
  std::map<std::string, int> by_callback;
  for (const auto& e : r.records("plugin-error")) {
    EXPECT_EQ(e["from"], "Bad");
    ++by_callback[e["callback"].get<std::string>()];
  }
  EXPECT_EQ(by_callback,
            (std::map<std::string, int>{
                {"on_delivery", 3}, {"start", 1}, {"stop", 1}, {"tick", 5}, {"timer", 1}}));
  auto errors = r.records("plugin-error");
  EXPECT_EQ(errors[0]["message"], "start failed");
  std::string reports = joined(r.reports);
  EXPECT_NE(reports.find("Bad: on_delivery threw: no such object 1"), std::string::npos) << reports;
  EXPECT_NE(reports.find("Bad: on_delivery threw: an exception that is not a std::exception"),
            std::string::npos)
      << reports;
  EXPECT_NE(reports.find("Bad: timer threw: timer failed"), std::string::npos) << reports;
  EXPECT_NE(r.table.find("Bad: 11 exception(s) caught, the run went on"), std::string::npos)
      << r.table;
  // Reported once per distinct text, not once per throw: start, three on_delivery texts,
  // tick, timer, stop.
  EXPECT_EQ(r.reports.size(), 7u) << reports;
}

TEST(FaultInjectionTest, ModuleWhoseConstructorThrowsIsAClearError) {
  TestApp t;
  t.registry.add_module("Broken",
                        []() -> std::unique_ptr<Module> { throw std::runtime_error("no camera"); });
  t.registry.add_module("Null", []() -> std::unique_ptr<Module> { return nullptr; });
  t.module("Broken", {"out x: int"});
  std::string error;
  EXPECT_FALSE(Runtime::create(t.app, t.dir, {}, &error, t.registry));
  EXPECT_EQ(error, "module 'Broken' could not be created: its constructor threw: no camera");
  t.app.modules[0].name = "Null";
  EXPECT_FALSE(Runtime::create(t.app, t.dir, {}, &error, t.registry));
  EXPECT_EQ(error, "module 'Null' could not be created: its factory returned no object");
}

// --- messages the runtime cannot take ----------------------------------------------------

TEST(FaultInjectionTest, MistypedMessageIsDroppedOnEachConnectionOfThePort) {
  Fault f;
  f.source = "Src2.w";
  f.inject = [](Runtime& rt) {
    TestApp::publish_at(rt, 1.5, "Src2", "w", Value(10));
    TestApp::publish_at(rt, 2.5, "Src2", "w", Value(std::string("ten")));
    TestApp::publish_at(rt, 3.5, "Src2", "w", Value(1.5));
    TestApp::publish_at(rt, 3.6, "Src2", "nope", Value(1));  // not a port: no connection
  };
  FaultRun r = run(f);
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].arrived, 3u);
  EXPECT_EQ(r["faulty"].delivered, 1u);
  EXPECT_EQ(r["faulty"].drops(DropReason::BadType), 2u);
  EXPECT_EQ(all_drops(r["faulty"]), 2u);
  auto drops = r.records("drop", "faulty");
  ASSERT_EQ(drops.size(), 2u);
  EXPECT_EQ(drops[0]["t"], 2.5);
  EXPECT_EQ(drops[0]["reason"], "bad-type");
  EXPECT_EQ(drops[0]["detail"], "expected int, got string");
  EXPECT_EQ(drops[1]["t"], 3.5);
  auto publish_errors = r.records("publish-error");
  ASSERT_EQ(publish_errors.size(), 3u);
  EXPECT_EQ(publish_errors[0]["port"], "Src2.w");
  EXPECT_EQ(publish_errors[2]["port"], "Src2.nope");
  EXPECT_EQ(r.sink_got.at("faulty"), 1);
  EXPECT_NE(r.table.find(" bad-type"), std::string::npos) << r.table;  // a column of its own
}

TEST(FaultInjectionTest, BurstOverflowsOnlyItsOwnQueue) {
  Fault f;
  f.source = "Src2.w";
  f.options.queue_capacity = 16;
  f.inject = [](Runtime& rt) {
    rt.executor().post(2s, [&rt] {
      for (int i = 0; i < 1000; ++i) rt.publish("Src2", "w", Value(i));
    });
  };
  FaultRun r = run(f);
  expect_unaffected_and_accounted(r);
  EXPECT_EQ(r["faulty"].arrived, 1000u);
  EXPECT_EQ(r["faulty"].delivered, 16u);
  EXPECT_EQ(r["faulty"].drops(DropReason::QueueFull), 984u);
  EXPECT_EQ(all_drops(r["faulty"]), 984u);
  EXPECT_EQ(r["faulty"].pending, 0u);
  EXPECT_EQ(r.sink_got.at("faulty"), 16);
}

}  // namespace
}  // namespace arbc
