// The generated monitors in the runtime's own sandbox and PortMonitor implementation
// (runtime/lua_monitor.h): every table_clean monitor loads and creates there without touching
// the constraint (the runtime installs app.json's), and the take / feed / no-value paths
// behave with real Values.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "compiler/codegen/embedded_target.h"
#include "compiler/codegen/testing/lua_monitor_harness.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"
#include "runtime/lua_monitor.h"
#include "tests/support/tree_paths.h"

namespace arbc::codegen {
namespace {

using testing::PortContainer;

// The runtime's MonitorHost, backed by one port's container with a virtual clock.
class Host : public MonitorHost {
 public:
  Host(PortContainer* port, std::string owner) : port_(port), owner_(std::move(owner)) {}
  // The harness keeps seconds; the runtime's host interface is in nanoseconds.
  Nanos now() override { return nanos_from_seconds(port_->now()); }
  void set_event(std::string_view name, std::optional<Nanos> life) override {
    port_->set(std::string(name), owner_,
               life ? std::optional<double>(seconds_of(*life)) : std::nullopt);
  }
  void unset_event(std::string_view name) override { port_->unset(std::string(name), owner_); }
  bool has_event(std::string_view name) override { return port_->has(std::string(name)); }
  bool set_constraint(std::string_view text, std::string*) override {
    constraint = text;  // recorded: a generated monitor must never call it
    return true;
  }
  std::string get_constraint() override { return constraint; }
  void set_trig_interval(Nanos) override {}
  void print(const std::string&) override {}
  std::string constraint;

 private:
  PortContainer* port_;
  std::string owner_;
};

struct Loaded {
  std::unique_ptr<Host> host;
  std::unique_ptr<LuaMonitor> monitor;
};

class RuntimeExecTest : public ::testing::Test {
 protected:
  void build(const std::string& text) {
    compiled_ = lower::compile_spec_text(text, "test.spec");
    ASSERT_TRUE(compiled_.ok) << frontend::render_diagnostics(compiled_.diagnostics,
                                                              &compiled_.sources);
    CodegenResult r = EmbeddedTarget().generate(*compiled_.lowered);
    ASSERT_TRUE(r.ok);
    for (const OutputFile& f : r.files) files_[f.path] = f.content;
  }
  Loaded& load(const model::Connection& c) {
    Loaded& l = loaded_[c.monitor];
    if (l.monitor) return l;
    l.host = std::make_unique<Host>(&ports_[c.destination], c.name);
    std::string error;
    l.monitor =
        LuaMonitor::load(files_[c.monitor], c.monitor, SandboxLimits{}, l.host.get(), &error);
    EXPECT_TRUE(l.monitor) << c.monitor << ": " << error;
    bool created = false;
    if (l.monitor) {
      LuaCall call = l.monitor->create({c.source, c.destination, c.name}, &created);
      EXPECT_TRUE(call.ok()) << call.error;
    }
    EXPECT_TRUE(created) << c.monitor;
    return l;
  }
  const model::Connection& connection(const std::string& port, const std::string& name) {
    for (const model::Connection& c : compiled_.lowered->app.connections)
      if (c.destination == port && c.name == name) return c;
    ADD_FAILURE() << "no connection " << name << " into " << port;
    return compiled_.lowered->app.connections.front();
  }

  lower::CompiledSpec compiled_;
  std::map<std::string, std::string> files_;
  std::map<std::string, PortContainer> ports_;
  std::map<std::string, Loaded> loaded_;
};

Value object(double x, double dist) {
  return Value::record({{"pos", Value::vec3(x, 0, 0)}, {"dist", dist}});
}

TEST_F(RuntimeExecTest, EveryTableCleanMonitorLoadsInTheRuntimeSandbox) {
  std::ifstream in(arbc::testing::source_dir() + "/specs/table_clean.spec");
  build(std::string(std::istreambuf_iterator<char>(in), {}));
  ASSERT_FALSE(HasFatalFailure());
  for (const model::Connection& c : compiled_.lowered->app.connections) {
    Loaded& l = load(c);
    ASSERT_TRUE(l.monitor);
    EXPECT_EQ(l.host->constraint, "") << c.monitor << " calls setConstraint";
  }

  // PickAndPlace.cmd: the status feed fills the container, then take delivers.
  Loaded& c3 = load(connection("PickAndPlace.cmd", "feed_PickAndPlace_status"));
  Loaded& c5 = load(connection("PickAndPlace.cmd", "feed_PullObject_status"));
  bool accepted = true;
  ASSERT_TRUE(c3.monitor->accept(Value::list({"e_arm_idle"}), &accepted).ok());
  EXPECT_FALSE(accepted);
  ASSERT_TRUE(c5.monitor->accept(Value::list({"e_pull_idle"}), &accepted).ok());
  EXPECT_EQ(ports_["PickAndPlace.cmd"].present(),
            (std::vector<std::string>{"e_arm_idle", "e_pull_idle"}));

  Loaded& take = load(connection("PickAndPlace.cmd", "take"));
  ASSERT_TRUE(
      take.monitor->accept(Value::list({object(0.9, 0.9), object(0.3, 0.3)}), &accepted).ok());
  EXPECT_TRUE(accepted);
  Value out;
  TypePtr cmd = parse_type("{verb: string, pos: vec3}");
  LuaCall u = take.monitor->update(*cmd, &out);
  ASSERT_TRUE(u.ok()) << u.error;
  EXPECT_EQ(out.to_json(), "{\"pos\":{\"x\":0.3,\"y\":0.0,\"z\":0.0},\"verb\":\"take\"}");

  // The derived-event feed with a real list of records.
  Loaded& c7 = load(connection("HeadControl.gaze", "feed_ObjectDetector_objects"));
  ASSERT_TRUE(c7.monitor->accept(Value::list({object(0.9, 0.9)}), &accepted).ok());
  EXPECT_EQ(ports_["HeadControl.gaze"].present(), (std::vector<std::string>{"e_unreachable"}));
}

TEST_F(RuntimeExecTest, MissingValueIsTheRuntimesNoValueNotAnError) {
  build(R"(app t;
type Object = { pos: vec3, dist: float };
module Eye  { out objects: list<Object>; }
module Head { in gaze: vec3; }
event a;
event e_near = Eye.objects : min_by(objects, o => o.dist).dist < 1.0;
arbitrate Head.gaze {
  near: from Eye.objects when a and e_near { emit min_by(objects, o => o.dist).pos; }
}
)");
  ASSERT_FALSE(HasFatalFailure());
  Loaded& near = load(connection("Head.gaze", "near"));
  bool accepted = true;
  LuaCall call = near.monitor->accept(Value::list({}), &accepted);
  EXPECT_EQ(call.status, LuaCall::Status::NoValue) << call.error;
  ASSERT_TRUE(near.monitor->accept(Value::list({object(2, 2)}), &accepted).ok());
  EXPECT_TRUE(accepted);
  // The feed re-raises the missing value after updating what it could.
  Loaded& feed = load(connection("Head.gaze", "feed_Eye_objects"));
  EXPECT_EQ(feed.monitor->accept(Value::list({}), &accepted).status, LuaCall::Status::NoValue);
  ASSERT_TRUE(feed.monitor->accept(Value::list({object(0.5, 0.5)}), &accepted).ok());
  EXPECT_EQ(ports_["Head.gaze"].present(), (std::vector<std::string>{"e_near"}));
}

}  // namespace
}  // namespace arbc::codegen
