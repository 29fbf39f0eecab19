#include "runtime/trace.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/json_text.h"
#include "runtime/runtime_test_util.h"

namespace arbc {

using namespace std::chrono_literals;
namespace {

using testing::TestApp;

// Runs the noisy app for 20 s; the trace goes to <dir>/<name>.jsonl, and to *records if given.
std::string run_traced(uint64_t seed, const std::string& name,
                       std::vector<TraceRecord>* records = nullptr) {
  TestApp t;
  add_noisy_app(t);
  t.connect("rule", "Noisy.x", "Sink.x", "e",
            "PortMonitor.accept = function(m) return m % 5 ~= 0 end\n"
            "PortMonitor.update = function(m) if m % 7 == 0 then PortMonitor.novalue() end "
            "return m end\n");
  RunOptions o;
  o.seed = seed;
  o.duration = 20;
  o.trace_path = t.dir + "/" + name + ".jsonl";
  o.trace_records = records;
  auto rt = t.start(o);
  rt->advance(20s);
  rt->shutdown();
  std::ifstream in(o.trace_path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(TraceTest, SameSeedGivesByteIdenticalTraces) {
  std::string a = run_traced(7, "a"), b = run_traced(7, "b"), c = run_traced(8, "c");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  for (const char* kind :
       {"\"type\":\"publish\"", "\"type\":\"deliver\"", "\"reason\":\"feed\"",
        "\"reason\":\"rejected\"", "\"reason\":\"not-selected\"", "\"reason\":\"no-value\"",
        "\"op\":\"set\"", "\"op\":\"unset\"", "\"op\":\"expire\""}) {
    EXPECT_NE(a.find(kind), std::string::npos) << kind;
  }
}

// The in-memory records (what --report reads) are the file's lines, one for one.
TEST(TraceTest, RecordsInMemoryMatchTheFileLineForLine) {
  std::vector<TraceRecord> records;
  std::string text = run_traced(7, "mem", &records);
  std::istringstream lines(text);
  std::string line;
  size_t i = 0;
  static const char* kTypes[] = {"deliver",    "drop",   "event",         "error",
                                 "quarantine", "log",    "publish-error", "plugin-error",
                                 "pending",    "publish"};
  while (std::getline(lines, line)) {
    ASSERT_LT(i, records.size()) << line;
    const TraceRecord& r = records[i++];
    std::string type = "\"type\":\"" + std::string(kTypes[static_cast<int>(r.kind)]) + "\"";
    EXPECT_NE(line.find(type), std::string::npos) << line;
    std::string t;
    append_json_seconds(t, r.t);
    EXPECT_EQ(line.rfind("{\"t\":" + t + ",", 0), 0u) << line;
    if (r.kind == TraceKind::Drop) {
      EXPECT_NE(line.find(std::string("\"reason\":\"") + drop_reason_name(r.reason) + "\""),
                std::string::npos)
          << line;
    }
    if (r.kind == TraceKind::Event) {
      EXPECT_NE(line.find("\"op\":\"" + r.op + "\",\"event\":\"" + r.event + "\""),
                std::string::npos)
          << line;
    }
  }
  EXPECT_EQ(i, records.size());
  EXPECT_GT(records.size(), 100u);
}

TEST(TraceTest, PluginErrorsAreRecordedInMemoryToo) {
  std::vector<TraceRecord> records;
  Trace trace;
  trace.record_to(&records);
  trace.plugin_error(4500ms, "PickAndPlace", "tick", "std::runtime_error: arm jammed");
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].kind, TraceKind::PluginError);
  EXPECT_EQ(records[0].t, 4500ms);
  EXPECT_EQ(records[0].connection, "PickAndPlace");
  EXPECT_EQ(records[0].callback, "tick");
  EXPECT_EQ(records[0].text, "std::runtime_error: arm jammed");
}

TEST(TraceTest, LineFormat) {
  TestApp t;
  RunOptions unused;
  Trace trace;
  std::string path = t.dir + "/t.jsonl";
  std::string err;
  ASSERT_TRUE(trace.open(path, &err)) << err;
  trace.publish(1500ms, "ObjectDetector.objects", Value::list({Value::record({{"dist", 0.3}})}));
  trace.delivery(1500ms, "take", "PickAndPlace.cmd", Value::record({{"verb", "take"}}));
  trace.drop(2s, "put", DropReason::NotSelected, "");
  trace.event(2250ms, "Speak.text", "set", "e_face", "feed_face", 3250ms);
  trace.error(3s + 1ns, "ask", "monitors/ask.lua:3: boom");
  trace.close();
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "{\"t\":1.5,\"type\":\"publish\",\"port\":\"ObjectDetector.objects\","
            "\"value\":[{\"dist\":0.3}]}\n"
            "{\"t\":1.5,\"type\":\"deliver\",\"connection\":\"take\",\"port\":\"PickAndPlace.cmd\","
            "\"value\":{\"verb\":\"take\"}}\n"
            "{\"t\":2.0,\"type\":\"drop\",\"connection\":\"put\",\"reason\":\"not-selected\"}\n"
            "{\"t\":2.25,\"type\":\"event\",\"port\":\"Speak.text\",\"op\":\"set\",\"event\":"
            "\"e_face\",\"owner\":\"feed_face\",\"expiry\":3.25}\n"
            "{\"t\":3.000000001,\"type\":\"error\",\"connection\":\"ask\",\"message\":"
            "\"monitors/ask.lua:3: boom\"}\n");
}

}  // namespace
}  // namespace arbc
