// harness/run_inputs.h: an inputs file (or a trace) read into the stand-ins' inputs, every line
// checked against the app before the run, the first bad one named at its place.
#include "harness/run_inputs.h"

#include <fstream>

#include "harness/harness_test_util.h"

namespace arbc::harness {
namespace {

struct Read {
  bool ok = false;
  std::string err;
  InputsRead read;
  StandInLog log;
};

Read read_lines(const std::string& lines) {
  auto lowered = testing::compiled(testing::kGaze);
  std::string path = testing::scratch() + "/in.jsonl";
  std::ofstream(path) << lines;
  Read r;
  r.ok = read_inputs(path, lowered->app, {"FaceDetector", "LookAround", "HeadControl"}, &r.log,
                     &r.read, &r.err);
  if (!r.ok) r.err = r.err.substr(r.err.rfind('/') + 1);  // from the file's name on
  return r;
}

// In time order, and at one instant in the file's order whatever the modules (issue 39: they
// were kept per module, and each module's stand-in published its own at the instant).
TEST(RunInputsTest, LinesAndTracePublicationsBecomeInputsInTimeOrder) {
  Read r = read_lines(
      "{\"t\": 0.5, \"port\": \"LookAround.gaze\", \"value\": [1, 0, 0]}\n"
      "\n"
      "{\"t\": 0.2, \"port\": \"LookAround.gaze\", \"value\": {\"x\": 0, \"y\": 1, \"z\": 0}}\n"
      "{\"t\": 0.5, \"port\": \"FaceDetector.face\", \"value\": {\"pos\": [0, 0, 1], "
      "\"certainty\": 0.9}}\n");
  ASSERT_TRUE(r.ok) << r.err;
  EXPECT_EQ(r.read.messages, 3u);
  EXPECT_FALSE(r.read.from_trace);
  const std::vector<TimedValue>& in = r.log.inputs();
  ASSERT_EQ(in.size(), 3u);
  EXPECT_EQ(in[0].t, std::chrono::milliseconds(200));
  EXPECT_EQ(in[1].port, "LookAround.gaze");
  EXPECT_EQ(in[2].port, "FaceDetector.face");
  EXPECT_EQ(in[2].t, std::chrono::milliseconds(500));
  Read trace = read_lines(
      "{\"t\":0.0,\"type\":\"publish\",\"port\":\"LookAround.gaze\",\"value\":{\"x\":1.0,"
      "\"y\":0.0,\"z\":0.0}}\n"
      "{\"t\":0.0,\"type\":\"drop\",\"connection\":\"search\",\"reason\":\"not-selected\"}\n");
  ASSERT_TRUE(trace.ok) << trace.err;
  EXPECT_TRUE(trace.read.from_trace);
  EXPECT_EQ(trace.read.messages, 1u);  // the drop is what that run did, not an input
}

TEST(RunInputsTest, TheFirstBadLineIsNamedAtItsPlace) {
  EXPECT_EQ(
      read_lines("{\"t\": \"100ms\", \"port\": \"LookAround.gaze\", \"value\": [1,0,0]}\n").err,
      "in.jsonl:1:7: field 't': \"100ms\" is a string; write 0.1, the time in seconds");
  EXPECT_EQ(read_lines("{\"t\": 1, \"port\": \"HeadControl.gaze\", \"value\": [1,0,0]}\n")
                .err.rfind("in.jsonl:1:18: field 'port': ", 0),
            0u);
  EXPECT_EQ(read_lines("{\"t\": 1, \"port\": \"LookAround.gaze\", \"value\": [1,\"a\",0]}\n").err,
            "in.jsonl:1:46: field 'value': field y: expected float, got string (port "
            "LookAround.gaze is vec3)");
  EXPECT_EQ(read_lines("not json\n").err.rfind("in.jsonl:1:", 0), 0u);
}

TEST(RunInputsTest, ADirectoryIsNotAnInputsFile) {
  auto lowered = testing::compiled(testing::kGaze);
  std::string dir = testing::scratch();
  InputsRead read;
  StandInLog log;
  std::string err;
  EXPECT_FALSE(read_inputs(dir, lowered->app, {"LookAround"}, &log, &read, &err));
  EXPECT_EQ(err, dir + ": a directory; --inputs takes a file of JSON lines (or a trace)");
}

}  // namespace
}  // namespace arbc::harness
