// harness/trace_diff.h: a trace file read back through the trace format, and the first decision
// in which two runs differ.
#include "harness/trace_diff.h"

#include <fstream>

#include "harness/harness_test_util.h"
#include "runtime/trace.h"

namespace arbc::harness {
namespace {

using namespace std::chrono_literals;

TraceRecord decision(Nanos t, const std::string& connection, bool delivered) {
  TraceRecord r;
  r.t = t;
  r.kind = delivered ? TraceKind::Deliver : TraceKind::Drop;
  r.connection = connection;
  r.port = "HeadControl.gaze";
  r.reason = DropReason::NotSelected;
  return r;
}

TEST(TraceDiffTest, ATraceFileReadsBackAsItsRecords) {
  std::string path = testing::scratch() + "/run.trace";
  std::vector<TraceRecord> written;
  {
    Trace trace;
    std::string err;
    ASSERT_TRUE(trace.open(path, &err)) << err;
    trace.record_to(&written);
    trace.delivery(500ms, "search", "HeadControl.gaze", Value::vec3(1, 0, 0));
    trace.drop(700ms, "search", DropReason::NotSelected, "");
    trace.event(700ms, "HeadControl.gaze", "set", "e_face", "feed", 1200ms);
  }
  std::vector<TraceRecord> read;
  std::string err;
  ASSERT_TRUE(read_trace_file(path, &read, &err)) << err;
  ASSERT_EQ(read.size(), written.size());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i].kind, written[i].kind);
    EXPECT_EQ(read[i].t, written[i].t);
    EXPECT_EQ(read[i].connection, written[i].connection);
  }
  std::ofstream(path, std::ios::app) << "{\"t\": 1, \"type\": \"deliverd\"}\n";
  EXPECT_FALSE(read_trace_file(path, &read, &err));
  EXPECT_NE(err.find("run.trace:4: not a trace record"), std::string::npos) << err;
}

TEST(TraceDiffTest, TheFirstDifferingDecisionIsNamed) {
  auto lowered = testing::compiled(testing::kGaze);
  std::vector<TraceRecord> a = {decision(100ms, "search", true), decision(200ms, "search", true)};
  std::vector<TraceRecord> b = {decision(100ms, "search", true), decision(200ms, "search", false)};
  EXPECT_EQ(first_difference(lowered->app, a, a, "other.trace"), "");
  std::string d = first_difference(lowered->app, a, b, "other.trace");
  EXPECT_NE(d.find("first difference: connection search into HeadControl.gaze, its message 2, "
                   "at 200ms"),
            std::string::npos)
      << d;
  EXPECT_NE(d.find("this run: delivered"), std::string::npos) << d;
  EXPECT_NE(d.find("other.trace: dropped (not-selected)"), std::string::npos) << d;
}

}  // namespace
}  // namespace arbc::harness
