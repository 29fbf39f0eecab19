// `arbc build --target yarp` on real YARP (docs/yarp.md#the-proof-on-real-yarp): a recorded run
// of the embedded runtime (`arbc run --trace`) is replayed onto YARP ports wired by the
// generated application XML and monitors, and each destination port must receive what the
// runtime delivered there: the same messages, in the same order. The replay follows the trace's
// clock on the wall clock, so a decision within kTolerance of an event's expiry (or a
// throttle's end) may go either way; those are counted, not failed.
#include <gmock/gmock.h>
#include <yarp/os/Time.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/app_json.h"
#include "core/instant.h"
#include "tests/yarp_real/bottle_layout.h"
#include "tests/yarp_real/replay_trace.h"
#include "tests/yarp_real/yarp_fixture.h"

namespace arbc::yarp_test {
namespace {

namespace fs = std::filesystem;

constexpr double kTolerance = 0.06;        // seconds; see docs/yarp.md#the-proof-on-real-yarp
constexpr double kSameInstantGap = 0.004;  // between messages the trace publishes at one instant

struct Case {
  std::string spec;      // relative to the source tree
  std::string plugin;    // path of the modules' plugin; empty: stand-ins (`arbc run --stub`)
  std::string scenario;  // empty: the environment's default
  std::string duration;  // of the recorded run
  double window;         // seconds of it replayed
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `command` (through the shell, output to `log`); its exit status.
int shell(const std::string& command, const fs::path& log) {
  std::string full = command + " > '" + log.string() + "' 2>&1";
  int rc = std::system(full.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

class YarpTargetTest : public YarpTest {
 protected:
  void SetUp() override {
    YarpTest::SetUp();
    char pattern[] = "/tmp/arbc-yarp-target-XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    YarpTest::TearDown();
    std::error_code ec;
    if (!HasFailure()) fs::remove_all(dir_, ec);
  }

  // Builds only the yarp target of `spec` (a path, absolute or in the source tree) with the
  // build options `options`; fills yarp_dir_ and ports_.
  void build_yarp(const std::string& spec, const std::string& app,
                  const std::string& options = "") {
    std::string arbc = ARBC_BINARY;
    std::string path = fs::path(spec).is_absolute() ? spec : source_dir(spec);
    ASSERT_EQ(shell(arbc + " build '" + path + "' --target yarp " + options + " -o '" +
                        (dir_ / "yarp").string() + "'",
                    dir_ / "build-yarp.log"),
              0)
        << slurp(dir_ / "build-yarp.log");
    yarp_dir_ = dir_ / "yarp" / app;
    ports_ = nlohmann::json::parse(slurp(yarp_dir_ / "ports.json"));
  }

  // Records the run, builds both targets; fills app_ and ports_.
  void record_and_build(const Case& c) {
    std::string spec = source_dir(c.spec);
    std::string arbc = ARBC_BINARY;
    ASSERT_EQ(shell(arbc + " build '" + spec + "' -o '" + (dir_ / "embedded").string() + "'",
                    dir_ / "build.log"),
              0)
        << slurp(dir_ / "build.log");
    ASSERT_EQ(
        shell(arbc + " build '" + spec + "' --target yarp -o '" + (dir_ / "yarp").string() + "'",
              dir_ / "build-yarp.log"),
        0)
        << slurp(dir_ / "build-yarp.log");
    fs::path app_dir = *fs::directory_iterator(dir_ / "embedded");
    std::string error;
    std::optional<model::App> app = model::from_app_json(slurp(app_dir / "app.json"), &error);
    ASSERT_TRUE(app) << error;
    app_ = *app;
    std::string modules = c.plugin.empty() ? " --stub" : " --plugin '" + c.plugin + "'";
    std::string run = arbc + " run '" + app_dir.string() + "'" + modules + " --seed 1 --duration " +
                      c.duration + " --trace '" + (dir_ / "trace.jsonl").string() + "'";
    if (!c.scenario.empty()) run += " --scenario " + c.scenario;
    int rc = shell(run, dir_ / "run.log");
    ASSERT_TRUE(rc == 0 || rc == 3) << slurp(dir_ / "run.log");  // 3: the world's verdict
    yarp_dir_ = dir_ / "yarp" / app_.name;
    ports_ = nlohmann::json::parse(slurp(yarp_dir_ / "ports.json"));
  }

  // Wires the generated application: the receiver opens the destinations, the test the sources.
  void wire() {
    std::string context = ports_["context"];
    add_context(context, (yarp_dir_ / "contexts" / context).string());
    std::vector<std::string> destinations;
    for (const nlohmann::json& l : ports_["connections"]) {
      writer(l["from"]);
      if (std::find(destinations.begin(), destinations.end(), l["to"]) == destinations.end())
        destinations.push_back(l["to"]);
    }
    start_receiver(destinations);
    for (const nlohmann::json& l : ports_["connections"])
      ASSERT_TRUE(connect(l["from"], l["to"], l["carrier"])) << l.dump();
  }

  TypePtr type_of(const std::string& port) {
    return parse_type(ports_["ports"][port]["type"].get<std::string>());
  }

  // Publishes the run's inputs on the wall clock: each at its trace time from now.
  void replay(const RecordedRun& run) {
    double start = ::yarp::os::Time::now() + 0.5, last_t = -1, offset = 0;
    for (const Publish& p : run.publishes) {
      offset = p.t == last_t ? offset + kSameInstantGap : 0;
      last_t = p.t;
      double wait = start + p.t + offset - ::yarp::os::Time::now();
      if (wait > 0) ::yarp::os::Time::delay(wait);
      auto& port = writer(ports_["ports"][p.port]["yarp"].get<std::string>());
      write_value(port.prepare(), p.value, *type_of(p.port));
      port.writeStrict();
    }
  }

  void run_case(const Case& c) {
    ASSERT_NO_FATAL_FAILURE(record_and_build(c));
    std::map<std::string, std::string> destination;
    std::map<std::string, double> throttle;
    for (const model::Connection& conn : app_.connections) {
      destination[conn.name] = conn.destination;
      if (conn.throttle) throttle[conn.name] = seconds_of(*conn.throttle);
    }
    RecordedRun run;
    std::string err;
    ASSERT_TRUE(read_recorded_run((dir_ / "trace.jsonl").string(), destination, throttle, c.window,
                                  kTolerance, &run, &err))
        << err;
    ASSERT_FALSE(run.publishes.empty());
    ASSERT_NO_FATAL_FAILURE(wire());
    replay(run);
    compare(run);
    EXPECT_TRUE(receiver_alive());
  }

  void compare(const RecordedRun& run) {
    std::map<std::string, std::vector<std::string>> expected;
    std::map<std::string, std::vector<bool>> sensitive;
    std::map<std::string, size_t> sensitive_drops;
    for (const Decision& d : run.decisions) {
      if (!d.delivered) {
        sensitive_drops[d.port] += d.sensitive ? 1 : 0;
        continue;
      }
      ::yarp::os::Bottle b;
      write_value(b, d.value, *type_of(d.port));
      expected[d.port].push_back(b.toString());
      sensitive[d.port].push_back(d.sensitive);
    }
    bool first = true;
    size_t total = 0;
    for (const auto& [port, info] : ports_["ports"].items()) {
      if (info["direction"] != "in") continue;
      std::vector<std::string> got = received(info["yarp"], first ? 1.5 : 0);
      first = false;
      PortComparison r = compare_deliveries(expected[port], sensitive[port], got);
      total += r.arbc;
      std::printf(
          "%s: arbc %zu, YARP %zu, matched %zu, sensitive not delivered %zu, extra %zu "
          "(sensitive drops %zu)\n",
          port.c_str(), r.arbc, r.yarp, r.matched, r.missing_sensitive, r.extra.size(),
          sensitive_drops[port]);
      EXPECT_TRUE(r.missing.empty())
          << port << ": arbc delivered, YARP did not: " << r.missing.front();
      EXPECT_LE(r.extra.size(), sensitive_drops[port])
          << port << ": YARP delivered what arbc did not: " << (r.extra.empty() ? "" : r.extra[0]);
      // The tolerance must stay the exception, or the test proves little.
      EXPECT_LE(r.missing_sensitive + r.extra.size(), r.arbc / 10 + 2) << port;
    }
    EXPECT_GT(total, 10u) << "the recorded run delivered almost nothing";
  }

  fs::path dir_, yarp_dir_;
  model::App app_;
  nlohmann::json ports_;
};

TEST_F(YarpTargetTest, TableCleanMixedRunDeliversTheSameOnYarp) {
  run_case({"specs/table_clean_yarp.spec", TABLE_CLEAN_PLUGIN, "mixed", "60s", 40.0});
}

TEST_F(YarpTargetTest, SearchAndTrackDeliversTheSameOnYarp) {
  run_case({"specs/search_and_track.spec", SEARCH_AND_TRACK_PLUGIN, "", "16s", 16.0});
}

// No simulated world shows face_filter's FaceDetector a face, so its modules are stand-ins: the
// detector publishes faces of random certainty at 10 Hz, and the monitor passes those of
// certainty 0.8 or more, as positions.
TEST_F(YarpTargetTest, FaceFilterStubRunDeliversTheSameOnYarp) {
  run_case({"specs/face_filter.spec", "", "", "10s", 10.0});
}

// A module that writes another layout than the spec's type (here a word where LookAround.gaze
// is a vec3) sees nothing arrive: the monitor says why once, on the receiver's stderr, with the
// Bottle it got and one it would take; the next such Bottle is dropped without a word, and a
// Bottle with the layout passes.
TEST_F(YarpTargetTest, ABottleWithoutTheLayoutIsDroppedAndSaidOnce) {
  ASSERT_NO_FATAL_FAILURE(build_yarp("specs/search_and_track.spec", "search_and_track"));
  ASSERT_NO_FATAL_FAILURE(wire());
  send("/LookAround/gaze:o", "left");
  send("/LookAround/gaze:o", "0.5 up");
  send("/LookAround/gaze:o", "0.5 0.25 1");
  EXPECT_THAT(received("/HeadControl/gaze:i"), ::testing::ElementsAre("0.5 0.25 1.0"));
  std::string log = receiver_log();
  std::string said =
      "arbc monitor HeadControl_gaze__search (/LookAround/gaze:o -> /HeadControl/gaze:i): "
      "dropped a message that is not a vec3 (LookAround.gaze) in arbc's Bottle layout, such as "
      "`0.0 0.0 0.0` (docs/yarp.md#the-bottle-layout): got `left`";
  EXPECT_NE(log.find(said), std::string::npos) << log;
  EXPECT_EQ(log.find("got `0.5 up`"), std::string::npos) << log;
  EXPECT_TRUE(receiver_alive());
}

// The runtime checks a YARP monitor carries (docs/yarp.md#runtime-checks). checks.spec's proof
// assumes lists of at most 4 elements: the monitor drops a longer one, says so once on the
// receiver's stderr, and passes the next message.
TEST_F(YarpTargetTest, RuntimeChecksDropAListLongerThanTheProofCovers) {
  ASSERT_NO_FATAL_FAILURE(build_yarp("tests/yarp_real/checks.spec", "yarp_checks"));
  ASSERT_NO_FATAL_FAILURE(wire());
  send("/Sensor/v:o", "1.0 2.0 3.0 4.0 4.5");
  send("/Sensor/v:o", "1.0 2.0 3.0 4.0 4.5 1.0");
  send("/Sensor/v:o", "1.0 2.0");
  send("/Sensor/v:o", "1.0 2.0 3.0 4.5");  // at the bound: delivered
  EXPECT_THAT(received("/Motor/cmd:i"), ::testing::ElementsAre("4.0", "9.0"));
  std::string log = receiver_log();
  std::string said =
      "arbc monitor Motor_cmd__pass (/Sensor/v:o -> /Motor/cmd:i): runtime check: dropped a "
      "message with a list of 5 elements; the proof of 'pass' covers at most 4 (bad-value; later "
      "ones are counted)";
  EXPECT_NE(log.find(said), std::string::npos) << log;
  EXPECT_EQ(log.find("a list of 6 elements"), std::string::npos) << log;
  EXPECT_TRUE(receiver_alive());
}

// The same app without the `accept` that keeps its assert over `emitted`, built with
// --no-verify: the monitor delivers what the rule emits and says on the first breach which
// value broke the assert; values that keep it pass without a word.
TEST_F(YarpTargetTest, RuntimeChecksSayABrokenAssertOverEmitted) {
  std::string text = slurp(source_dir("tests/yarp_real/checks.spec"));
  const std::string keep = "    accept hi < 5.0;\n";
  ASSERT_NE(text.find(keep), std::string::npos);
  text.erase(text.find(keep), keep.size());
  fs::path broken = dir_ / "broken.spec";
  std::ofstream(broken) << text;
  ASSERT_NO_FATAL_FAILURE(build_yarp(broken.string(), "yarp_checks", "--no-verify"));
  ASSERT_NO_FATAL_FAILURE(wire());
  send("/Sensor/v:o", "1.0 2.0");
  send("/Sensor/v:o", "1.0 6.0");
  send("/Sensor/v:o", "7.0");
  EXPECT_THAT(received("/Motor/cmd:i"), ::testing::ElementsAre("4.0", "12.0", "14.0"));
  std::string log = receiver_log();
  std::string said =
      "arbc monitor Motor_cmd__pass (/Sensor/v:o -> /Motor/cmd:i): runtime check: assert "
      "Motor.cmd: pass -> emitted < 10.0 broken: 'pass' delivered `12.0`, for which it is false "
      "(later breaches are counted)";
  EXPECT_NE(log.find(said), std::string::npos) << log;
  EXPECT_EQ(log.find("delivered `14.0`"), std::string::npos) << log;
  EXPECT_TRUE(receiver_alive());
}

// The checks of time (tests/yarp_real/timing.spec): the app without its throttle, built with
// --no-verify, delivers messages less than 1 s apart (each send takes about 0.2 s, less than
// the 500 ms rate), and the monitor says which property that breaks, once.
TEST_F(YarpTargetTest, RuntimeChecksSayTwoDeliveriesCloserThanTheProofSays) {
  std::string text = slurp(source_dir("tests/yarp_real/timing.spec"));
  const std::string keep = "    throttle 1s;\n";
  ASSERT_NE(text.find(keep), std::string::npos);
  text.erase(text.find(keep), keep.size());
  fs::path broken = dir_ / "broken.spec";
  std::ofstream(broken) << text;
  ASSERT_NO_FATAL_FAILURE(build_yarp(broken.string(), "yarp_timing", "--no-verify"));
  ASSERT_NO_FATAL_FAILURE(wire());
  send("/Sensor/v:o", "1.0");
  send("/Sensor/v:o", "2.0");
  send("/Sensor/v:o", "3.0");
  EXPECT_THAT(received("/Motor/cmd:i"), ::testing::ElementsAre("1.0", "2.0", "3.0"));
  std::string log = receiver_log();
  std::string said =
      "arbc monitor Motor_cmd__pass (/Sensor/v:o -> /Motor/cmd:i): runtime check: never two pass "
      "within 1s broken: 'pass' delivered twice 0.";
  size_t at = log.find(said);
  ASSERT_NE(at, std::string::npos) << log;
  EXPECT_EQ(log.find(said, at + 1), std::string::npos) << log;  // later breaches are counted
  EXPECT_EQ(log.find("given Sensor.v"), std::string::npos) << log;
  EXPECT_TRUE(receiver_alive());
}

// The app as proved: its throttle keeps the spacing (nothing said of it), and a silence of the
// source longer than the `given` rate is said when the next message comes.
TEST_F(YarpTargetTest, RuntimeChecksSayASourceSilentLongerThanItsRate) {
  ASSERT_NO_FATAL_FAILURE(build_yarp("tests/yarp_real/timing.spec", "yarp_timing"));
  ASSERT_NO_FATAL_FAILURE(wire());
  send("/Sensor/v:o", "1.0");
  send("/Sensor/v:o", "2.0");  // throttled
  EXPECT_THAT(received("/Motor/cmd:i", 1.2), ::testing::ElementsAre("1.0"));
  send("/Sensor/v:o", "3.0");
  EXPECT_THAT(received("/Motor/cmd:i"), ::testing::ElementsAre("3.0"));
  std::string log = receiver_log();
  std::string said =
      "arbc monitor Motor_cmd__pass (/Sensor/v:o -> /Motor/cmd:i): runtime check: assumption "
      "given Sensor.v every 500ms broken: nothing from Sensor.v for ";
  EXPECT_NE(log.find(said), std::string::npos) << log;
  EXPECT_EQ(log.find("never two pass"), std::string::npos) << log;
  EXPECT_TRUE(receiver_alive());
}

// Sized numbers (tests/yarp_real/sized.spec): a Bottle whose int8 holds 300 or whose float32
// holds a float64 that would round is dropped as without the layout; 2^64 - 1, sent as the int64
// -1, is greater than 5 for the uint64 comparison (math.ult), so it is delivered; 3 is not.
TEST_F(YarpTargetTest, SizedNumbersAreReadWithinTheirTypes) {
  ASSERT_NO_FATAL_FAILURE(build_yarp("tests/yarp_real/sized.spec", "yarp_sized"));
  ASSERT_NO_FATAL_FAILURE(wire());
  send("/Sensor/r:o", "(level 300) (count 1) (seq 9) (range 0.5)");
  send("/Sensor/r:o", "(level 1) (count 1) (seq 9) (range 0.1)");
  send("/Sensor/r:o", "(level 1) (count 1) (seq 3) (range 0.5)");
  send("/Sensor/r:o", "(level -128) (count 65535) (seq -1) (range 0.5)");
  EXPECT_THAT(received("/Motor/r:i"),
              ::testing::ElementsAre("(level -128) (count 65535) (seq -1) (range 0.5)"));
  std::string log = receiver_log();
  EXPECT_NE(log.find("got `(level 300) (count 1) (seq 9) (range 0.5)`"), std::string::npos) << log;
  EXPECT_TRUE(receiver_alive());
}

}  // namespace
}  // namespace arbc::yarp_test
