// PickAndPlace on the embedded runtime: its status goes out at the simulated instant it
// changes (not at the next 10 Hz report), and at 10 Hz in between.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "examples/table_clean/modules/world_environment.h"
#include "runtime/runtime.h"

namespace arbc::table_clean {

using namespace std::chrono_literals;
namespace {

// Test-only modules: a command source and a recorder of status messages.
class CmdSource : public arbc::Module {
 public:
  CmdSource() { out("cmd", "{verb: string, pos: vec3}"); }
};
std::vector<std::pair<double, std::vector<std::string>>>* g_recorded = nullptr;
class StatusRecorder : public arbc::Module {
 public:
  StatusRecorder() { in("status", "list<string>"); }
  void on_message(const std::string&, const arbc::Value& v) override {
    std::vector<std::string> flags;
    for (const arbc::Value& f : v.as_list()) flags.push_back(f.as_string());
    g_recorded->emplace_back(now(), flags);
  }
};
ARBC_REGISTER_MODULE(CmdSource, "TestCmdSource");
ARBC_REGISTER_MODULE(StatusRecorder, "TestStatusRecorder");

model::App app() {
  auto port = [](std::string name, model::Direction d, const char* type) {
    model::Port p;
    p.name = std::move(name);
    p.direction = d;
    p.type = parse_type(type);
    return p;
  };
  const char* kCmd = "{verb: string, pos: vec3}";
  model::App a;
  a.name = "table_clean";
  a.modules = {
      {"PickAndPlace",
       "",
       {port("cmd", model::Direction::In, kCmd),
        port("status", model::Direction::Out, "list<string>")},
       {}},
      {"TestCmdSource", "", {port("cmd", model::Direction::Out, kCmd)}, {}},
      {"TestStatusRecorder", "", {port("status", model::Direction::In, "list<string>")}, {}},
  };
  auto connect = [](std::string name, std::string from, std::string to) {
    model::Connection c;
    c.name = std::move(name);
    c.source = std::move(from);
    c.destination = std::move(to);
    c.kind = model::ConnectionKind::Connect;
    c.constraint = Constraint::constant(true);
    return c;
  };
  a.connections = {connect("cmd", "TestCmdSource.cmd", "PickAndPlace.cmd"),
                   connect("status", "PickAndPlace.status", "TestStatusRecorder.status")};
  return a;
}

TEST(PickAndPlaceModule, PublishesEachStatusChangeAtItsInstantAndAt10Hz) {
  std::vector<std::pair<double, std::vector<std::string>>> recorded;
  g_recorded = &recorded;
  RunOptions options;
  options.scenario = "reachable";
  options.duration = 10;
  std::string error;
  auto runtime = Runtime::create(app(), ".", options, &error);
  ASSERT_TRUE(runtime) << error;
  runtime->start();
  runtime->advance(950ms);
  World* world = dynamic_cast<WorldEnvironment&>(*runtime->environment()).world();
  const Vec3 target = world->objects()[0].pos;
  recorded.clear();
  runtime->publish("TestCmdSource", "cmd",
                   arbc::Value::record({{"verb", "take"}, {"pos", arbc::Value(target)}}));
  runtime->advance(nanos_from_seconds(0.95 + Arm::kTakeDuration + 0.05));
  runtime->shutdown();
  g_recorded = nullptr;

  const double t0 = 0.95;
  ASSERT_FALSE(recorded.empty());
  // The change to busy goes out at once...
  EXPECT_NEAR(recorded.front().first, t0, 1e-9);
  EXPECT_TRUE(recorded.front().second.empty());
  // ... the change to holding at exactly t0 + take duration, between two 10 Hz reports ...
  bool seen_holding = false;
  for (const auto& [t, flags] : recorded) {
    if (flags == std::vector<std::string>{"e_taken", "e_arm_idle"}) {
      EXPECT_NEAR(t, t0 + Arm::kTakeDuration, 1e-9);
      seen_holding = true;
      break;
    }
    EXPECT_TRUE(flags.empty()) << "at " << t;
  }
  EXPECT_TRUE(seen_holding);
  // ... and the 10 Hz reports in between: about 12 in 1.2 s.
  EXPECT_GE(recorded.size(), 12u);
  EXPECT_EQ(world->conflicts().total(), 0);
}

}  // namespace
}  // namespace arbc::table_clean
