// Escapes and faults: each fails cleanly, is counted and reported, and the process (and the
// rest of the app) keeps running (docs/runtime.md#the-sandbox).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "runtime/runtime_test_util.h"
#include "tests/support/tree_paths.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::TestApp;

struct Outcome {
  ConnectionStats bad, good;
  std::vector<std::string> reports;
  size_t delivered_good = 0;
};

// Runs `script` as the monitor of connection "bad" beside a healthy connection "good",
// sending three messages to each.
Outcome run_with(const std::string& script, RunOptions options = {}) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int", "in y: int"});
  t.connect("bad", "Src.x", "Sink.x", "true", script);
  t.connect("good", "Src.x", "Sink.y", "true",
            "PortMonitor.update = function(m) return m + 1 end\n");
  auto rt = t.start(options);
  for (int i = 0; i < 3; ++i) TestApp::publish_at(*rt, 1 + i, "Src", "x", Value(i));
  rt->advance(5s);
  rt->shutdown();
  Outcome o;
  o.bad = TestApp::stats_of(rt->stats(), "bad");
  o.good = TestApp::stats_of(rt->stats(), "good");
  o.reports = t.reports;
  for (const auto& g : TestApp::sink(*rt).got) o.delivered_good += g.connection == "good";
  return o;
}

std::string all(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

void expect_errors_in_accept(const std::string& body, const std::string& message_part) {
  SCOPED_TRACE(body);
  Outcome o = run_with("PortMonitor.accept = function(m)\n  " + body + "\n  return true\nend\n");
  EXPECT_EQ(o.bad.errors, 3u);
  EXPECT_EQ(o.bad.drops(DropReason::MonitorError), 3u);
  EXPECT_EQ(o.bad.delivered, 0u);
  EXPECT_EQ(o.delivered_good, 3u);
  // Reported once per distinct error, with file and line.
  ASSERT_EQ(o.reports.size(), 1u) << all(o.reports);
  EXPECT_NE(o.reports[0].find("monitors/bad.lua:2:"), std::string::npos) << o.reports[0];
  EXPECT_NE(o.reports[0].find(message_part), std::string::npos) << o.reports[0];
}

TEST(SandboxTest, NoOsIoRequireOrLoad) {
  std::string marker = arbc::testing::binary_dir() + "/sandbox_escaped";
  std::filesystem::remove(marker);
  expect_errors_in_accept("os.execute('touch " + marker + "')", "global 'os'");
  expect_errors_in_accept("io.open('" + marker + "', 'w')", "global 'io'");
  expect_errors_in_accept("require('os')", "global 'require'");
  expect_errors_in_accept("load('return 1')()", "global 'load'");
  expect_errors_in_accept("loadstring('return 1')()", "global 'loadstring'");
  expect_errors_in_accept("dofile('/etc/passwd')", "global 'dofile'");
  expect_errors_in_accept("debug.getinfo(1)", "global 'debug'");
  expect_errors_in_accept("string.dump(print)", "field 'dump'");
  EXPECT_FALSE(std::filesystem::exists(marker));
}

TEST(SandboxTest, InfiniteLoopHitsTheInstructionBudget) {
  RunOptions o;
  o.limits.instructions = 100000;
  Outcome r = run_with("PortMonitor.accept = function(m)\n  while true do end\nend\n", o);
  EXPECT_EQ(r.bad.errors, 3u);
  EXPECT_EQ(r.delivered_good, 3u);
  ASSERT_FALSE(r.reports.empty());
  EXPECT_NE(r.reports[0].find("monitors/bad.lua:2: instruction budget of 100000 exceeded"),
            std::string::npos)
      << r.reports[0];
}

TEST(SandboxTest, ScriptPcallCannotSwallowTheBudget) {
  RunOptions o;
  o.limits.instructions = 100000;
  Outcome r = run_with(
      "PortMonitor.accept = function(m)\n"
      "  while true do pcall(function() while true do end end) end\n"
      "end\n",
      o);
  EXPECT_EQ(r.bad.errors, 3u);
  EXPECT_EQ(r.delivered_good, 3u);
}

// The pattern of issue 13: exponential backtracking inside one C call, where the instruction
// hook never fires. It fails with the step budget's error and is handled as any failing monitor:
// counted, dropped, quarantined after repeated failures; the other connection is unaffected.
TEST(SandboxTest, CatastrophicPatternIsCountedAndQuarantined) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int", "in y: int"});
  t.connect("bad", "Src.x", "Sink.x", "true",
            "PortMonitor.accept = function(m)\n"
            "  return string.find(string.rep(\"a\", 40), string.rep(\"a?\", 40) .. "
            "string.rep(\"a\", 40) .. \"b\") ~= nil\n"
            "end\n");
  t.connect("good", "Src.x", "Sink.y", "true", "");
  auto start = std::chrono::steady_clock::now();
  auto rt = t.start();
  for (int i = 0; i < 7; ++i) TestApp::publish_at(*rt, 1 + i, "Src", "x", Value(i));
  rt->advance(10s);
  rt->shutdown();
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ConnectionStats bad = TestApp::stats_of(rt->stats(), "bad");
  EXPECT_EQ(bad.errors, 5u);
  EXPECT_EQ(bad.drops(DropReason::MonitorError), 5u);
  EXPECT_TRUE(bad.quarantined);
  EXPECT_EQ(bad.drops(DropReason::Quarantined), 2u);
  EXPECT_EQ(TestApp::stats_of(rt->stats(), "good").delivered, 7u);
  ASSERT_FALSE(t.reports.empty());
  EXPECT_NE(t.reports[0].find("monitors/bad.lua:2: string.find: work budget of 10000000 steps "
                              "exceeded"),
            std::string::npos)
      << t.reports[0];
  EXPECT_LT(seconds, 10.0);  // five budgets of well under a second each
}

// Coroutines run under the callback's one instruction budget: a loop that starts coroutines,
// each just under a budget of its own, still stops.
TEST(SandboxTest, CoroutinesShareTheCallbacksBudget) {
  RunOptions o;
  o.limits.instructions = 100000;
  o.limits.wall_seconds = 60;  // the instruction budget, not the clock, must stop it
  auto start = std::chrono::steady_clock::now();
  Outcome r = run_with(
      "PortMonitor.accept = function(m)\n"
      "  while true do coroutine.wrap(function() for i = 1, 99000 do end end)() end\n"
      "end\n",
      o);
  EXPECT_EQ(r.bad.errors, 3u);
  EXPECT_EQ(r.delivered_good, 3u);
  ASSERT_FALSE(r.reports.empty());
  EXPECT_NE(r.reports[0].find("instruction budget of 100000 exceeded"), std::string::npos)
      << r.reports[0];
  // Each coroutine counted on its own would let one callback run about 10^9 instructions.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

// update's result is read raw: a metamethod that raises does not run (it would have longjmp'd
// over the C++ value being built: a leak LeakSanitizer reports); the field is missing.
TEST(SandboxTest, UpdateResultIsReadWithoutRunningItsMetamethods) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: {verb: string, n: int}"});
  t.connect("c", "Src.x", "Sink.x", "true",
            "local boom = {__index = function() error('metamethod ran') end}\n"
            "PortMonitor.update = function(m) return setmetatable({verb = 'go'}, boom) end\n");
  auto rt = t.start();
  for (int i = 0; i < 3; ++i) TestApp::publish_at(*rt, 1 + i, "Src", "x", Value(i));
  rt->advance(5s);
  rt->shutdown();
  ConnectionStats c = TestApp::stats_of(rt->stats(), "c");
  EXPECT_EQ(c.drops(DropReason::MonitorError), 3u);
  ASSERT_FALSE(t.reports.empty());
  EXPECT_NE(t.reports[0].find("missing field n"), std::string::npos) << t.reports[0];
  EXPECT_EQ(t.reports[0].find("metamethod ran"), std::string::npos) << t.reports[0];
}

TEST(SandboxTest, MemoryBombHitsTheCap) {
  RunOptions o;
  o.limits.memory_bytes = 1 << 20;
  Outcome r = run_with(
      "PortMonitor.accept = function(m)\n"
      "  local t = {} for i = 1, 1e9 do t[i] = string.rep('x', 100) .. i end\n"
      "end\n",
      o);
  EXPECT_EQ(r.bad.errors, 3u);
  EXPECT_EQ(r.delivered_good, 3u);
  ASSERT_FALSE(r.reports.empty());
  EXPECT_NE(r.reports[0].find("memory cap of 1024 KiB exceeded"), std::string::npos)
      << r.reports[0];
  Outcome big =
      run_with("PortMonitor.accept = function(m) local s = string.rep('x', 1 << 40) end\n", o);
  EXPECT_EQ(big.bad.errors, 3u);
}

TEST(SandboxTest, ErrorInEachCallbackIsCountedAndContained) {
  // accept and update: the message is dropped.
  Outcome a = run_with("PortMonitor.accept = function(m) error('boom') end\n");
  EXPECT_EQ(a.bad.drops(DropReason::MonitorError), 3u);
  EXPECT_EQ(a.delivered_good, 3u);
  Outcome u = run_with("PortMonitor.update = function(m) error('bang') end\n");
  EXPECT_EQ(u.bad.drops(DropReason::MonitorError), 3u);
  EXPECT_NE(all(u.reports).find("monitors/bad.lua:1: bang"), std::string::npos) << all(u.reports);
  // create: the connection never runs (quarantined), the rest does.
  Outcome c = run_with("PortMonitor.create = function(o) error('no') end\n");
  EXPECT_TRUE(c.bad.quarantined);
  EXPECT_EQ(c.bad.drops(DropReason::Quarantined), 3u);
  EXPECT_EQ(c.delivered_good, 3u);
  // trig: counted as errors, messages unaffected.
  Outcome tr = run_with(
      "PortMonitor.create = function(o) PortMonitor.setTrigInterval(10) return true end\n"
      "PortMonitor.trig = function() error('tick') end\n");
  EXPECT_EQ(tr.bad.errors, 0u);  // first trig at t = 10, after the run
  EXPECT_EQ(tr.bad.delivered, 3u);
  Outcome tr2 = run_with(
      "PortMonitor.create = function(o) PortMonitor.setTrigInterval(2) return true end\n"
      "PortMonitor.trig = function() error('tick') end\n");
  EXPECT_EQ(tr2.bad.errors, 2u);  // trig at 2 and 4
  EXPECT_EQ(tr2.bad.delivered, 3u);
  // destroy: counted at shutdown.
  Outcome d = run_with("PortMonitor.destroy = function() error('bye') end\n");
  EXPECT_EQ(d.bad.errors, 1u);
  EXPECT_EQ(d.bad.delivered, 3u);
  // a non-string error object
  Outcome e = run_with("PortMonitor.accept = function(m) error({}) end\n");
  EXPECT_NE(all(e.reports).find("error object is a table value"), std::string::npos);
}

TEST(SandboxTest, HostileMetatablesAreContained) {
  Outcome o = run_with(
      "setmetatable(PortMonitor, {__index = function() error('gotcha') end})\n"
      "setmetatable(_G, {__index = function() error('gotcha') end})\n");
  // Looking up create raises: the connection is quarantined, nothing crashes, the rest runs.
  EXPECT_TRUE(o.bad.quarantined);
  EXPECT_EQ(o.bad.drops(DropReason::Quarantined), 3u);
  EXPECT_EQ(o.delivered_good, 3u);
}

TEST(SandboxTest, WrongReturnTypesAreErrors) {
  Outcome a = run_with("PortMonitor.accept = function(m) return 'yes' end\n");
  EXPECT_EQ(a.bad.drops(DropReason::MonitorError), 3u);
  EXPECT_NE(all(a.reports).find("accept must return a boolean, got string"), std::string::npos)
      << all(a.reports);
  Outcome n = run_with("PortMonitor.accept = function(m) end\n");
  EXPECT_NE(all(n.reports).find("accept must return a boolean, got nothing"), std::string::npos);
  Outcome u = run_with("PortMonitor.update = function(m) return {1} end\n");
  EXPECT_EQ(u.bad.drops(DropReason::MonitorError), 3u);
  EXPECT_NE(all(u.reports).find("expected int, got table"), std::string::npos) << all(u.reports);
  Outcome c = run_with("PortMonitor.create = function(m) return 3 end\n");
  EXPECT_TRUE(c.bad.quarantined);
  Outcome f = run_with("PortMonitor.create = function(m) return false end\n");
  EXPECT_TRUE(f.bad.quarantined);
  EXPECT_EQ(f.delivered_good, 3u);
}

TEST(SandboxTest, RepeatedFailuresQuarantineTheConnection) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect(
      "bad", "Src.x", "Sink.x", "true",
      "PortMonitor.accept = function(m) if m < 100 then error('bad ' .. m) end return true end\n");
  RunOptions o;
  o.quarantine_after = 4;
  auto rt = t.start(o);
  for (int i = 0; i < 10; ++i) TestApp::publish_at(*rt, i, "Src", "x", Value(i));
  TestApp::publish_at(*rt, 20, "Src", "x", Value(500));
  rt->advance(30s);
  auto s = TestApp::stats_of(rt->stats(), "bad");
  EXPECT_TRUE(s.quarantined);
  EXPECT_EQ(s.errors, 4u);
  EXPECT_EQ(s.drops(DropReason::MonitorError), 4u);
  EXPECT_EQ(s.drops(DropReason::Quarantined), 7u);
  EXPECT_EQ(s.delivered, 0u);
  EXPECT_NE(all(t.reports).find("connection bad quarantined"), std::string::npos);
}

TEST(SandboxTest, ScriptThatFailsToLoadIsAClearError) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Src.x", "Sink.x", "true", "PortMonitor.accept = function(m\n");
  std::string error;
  auto rt = Runtime::create(t.app, t.dir, {}, &error, t.registry);
  EXPECT_FALSE(rt);
  EXPECT_NE(error.find("monitors/c.lua:2:"), std::string::npos) << error;
  TestApp t2;
  t2.module("Src", {"out x: int"});
  t2.module("Sink", {"in x: int"});
  t2.connect("c", "Src.x", "Sink.x", "true", "while true do end\n");
  RunOptions o;
  o.limits.instructions = 10000;
  rt = Runtime::create(t2.app, t2.dir, o, &error, t2.registry);
  EXPECT_FALSE(rt);
  EXPECT_NE(error.find("instruction budget"), std::string::npos) << error;
}

TEST(SandboxTest, TooSmallMemoryCapIsAnErrorNotACrash) {
  for (size_t cap : {1024u, 8192u, 20000u}) {
    TestApp t;
    t.module("Src", {"out x: int"});
    t.module("Sink", {"in x: int"});
    t.connect("c", "Src.x", "Sink.x", "true",
              "PortMonitor.accept = function(m) return m > 0 end\n");
    RunOptions o;
    o.limits.memory_bytes = cap;
    std::string error;
    auto rt = Runtime::create(t.app, t.dir, o, &error, t.registry);
    if (!rt) {
      EXPECT_NE(error.find("monitors/c.lua"), std::string::npos) << error;
    }
  }
}

TEST(SandboxTest, MonitorStateIsSmall) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Src.x", "Sink.x", "true",
            "PortMonitor.accept = function(m) return m > 0 end\n"
            "PortMonitor.update = function(m) return m end\n");
  auto rt = t.start();
  size_t bytes = rt->monitor_memory().at("c");
  EXPECT_GT(bytes, 1000u);
  EXPECT_LE(bytes, 64u * 1024u);
}

}  // namespace
}  // namespace arbc
