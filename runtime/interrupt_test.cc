// An interrupt (Ctrl-C, SIGTERM: RunOptions::interrupt) ends a run promptly in any state, and
// what the executor thread runs is visible from another thread, so that a watchdog can name a
// callback that does not stop (docs/reliability.md, "A stuck monitor").
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::TestApp;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A monitor inside Lua's string.find with budgets so large that only the interrupt stops it.
TEST(InterruptTest, AnInterruptEndsARunWhileAMonitorIsInsideACFunction) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("stuck", "Src.x", "Sink.x", "true",
            "PortMonitor.accept = function(m)\n"
            "  return string.find(string.rep('a', 40), string.rep('a?', 40) .. "
            "string.rep('a', 40) .. 'b') ~= nil\n"
            "end\n");
  std::atomic<bool> interrupt{false};
  RunOptions options;
  options.interrupt = &interrupt;
  options.limits.library_steps = 1LL << 60;
  options.limits.wall_seconds = 3600;
  options.duration = 1000;
  std::vector<TraceRecord> records;
  options.trace_records = &records;
  std::string error;
  auto rt = Runtime::create(t.app, t.dir, options, &error, t.registry);
  ASSERT_TRUE(rt) << error;
  rt->set_reporter([&](const std::string& line) { t.reports.push_back(line); });
  for (int i = 0; i < 100; ++i) TestApp::publish_at(*rt, 1 + i, "Src", "x", Value(i));
  std::thread signal([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    interrupt = true;
  });
  auto start = std::chrono::steady_clock::now();
  rt->run();
  double seconds = seconds_since(start);
  signal.join();
  EXPECT_LT(seconds, 1.3);  // 0.3 s before the interrupt, then at once
  EXPECT_EQ(rt->stop_reason(), "interrupted");
  ConnectionStats s = TestApp::stats_of(rt->stats(), "stuck");
  EXPECT_EQ(s.errors, 1u);  // the message inside find when the interrupt came
  EXPECT_EQ(s.drops(DropReason::MonitorError), 1u);
  EXPECT_EQ(s.arrived, 1u);  // the run stopped before the next message
  ASSERT_FALSE(t.reports.empty());
  EXPECT_NE(t.reports[0].find("monitors/stuck.lua:2: interrupted"), std::string::npos)
      << t.reports[0];
  bool logged = false;
  for (const TraceRecord& r : records)
    logged |= r.kind == TraceKind::Log && r.text == "stop: interrupted";
  EXPECT_TRUE(logged);
}

// The real-time executor notices an interrupt while it sleeps until a far task.
TEST(InterruptTest, AnInterruptWakesTheRealtimeExecutor) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Src.x", "Sink.x", "true");
  std::atomic<bool> interrupt{false};
  RunOptions options;
  options.interrupt = &interrupt;
  options.realtime = true;
  options.duration = 60;
  auto rt = t.start(options);
  TestApp::publish_at(*rt, 50, "Src", "x", Value(1));
  std::thread signal([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    interrupt = true;
  });
  auto start = std::chrono::steady_clock::now();
  rt->run();
  signal.join();
  EXPECT_LT(seconds_since(start), 1.0);
  EXPECT_EQ(rt->stop_reason(), "interrupted");
}

// While a monitor is inside a C function (print, which hands the line to the run's log), another
// thread sees which monitor and callback it is; between callbacks, nothing.
TEST(InterruptTest, BusyNamesTheMonitorAndItsCallbackFromAnotherThread) {
  TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("chatty", "Src.x", "Sink.x", "true",
            "PortMonitor.accept = function(m) print('got', m) return true end\n");
  auto rt = t.start();
  std::atomic<bool> printing{false}, seen{false};
  std::string described;
  rt->set_reporter([&](const std::string&) {
    printing = true;
    while (!seen) std::this_thread::yield();  // the monitor stays inside print meanwhile
  });
  std::thread watchdog([&] {
    while (!printing) std::this_thread::yield();
    described = Runtime::describe(rt->busy());
    seen = true;
  });
  TestApp::publish_at(*rt, 1, "Src", "x", Value(7));
  rt->advance(2s);
  watchdog.join();
  EXPECT_EQ(described, "the monitor of connection 'chatty', in accept");
  EXPECT_EQ(Runtime::describe(rt->busy()), "");
  EXPECT_EQ(TestApp::stats_of(rt->stats(), "chatty").delivered, 1u);
}

}  // namespace
}  // namespace arbc
