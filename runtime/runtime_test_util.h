// Test helpers: an app built in code, monitor scripts written to a scratch directory, and
// two small modules (a source that publishes what the test tells it, a sink that records).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/sha256.h"
#include "runtime/runtime.h"
#include "tests/support/tree_paths.h"

namespace arbc::testing {

// Records every delivery it gets.
class Sink : public Module {
 public:
  struct Got {
    std::string port, connection;
    Value value;
    double time;
  };
  void on_delivery(const Delivery& d) override {
    got.push_back({d.port, d.connection, d.value, d.time});
  }
  std::vector<Got> got;
};

class Source : public Module {};

class TestApp {
 public:
  TestApp() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = arbc::testing::binary_dir() + "/runtime_test_scratch/" + info->test_suite_name() + "." +
          info->name();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir + "/monitors");
    registry.add_module("Src", [] { return std::make_unique<Source>(); });
    registry.add_module("Src2", [] { return std::make_unique<Source>(); });
    registry.add_module("Sink", [] { return std::make_unique<Sink>(); });
  }

  // Adds a module with ports given as {"in x: int", "out y: float"}.
  void module(const std::string& name, const std::vector<std::string>& ports) {
    model::Module m;
    m.name = name;
    for (const std::string& p : ports) {
      model::Port port;
      port.direction = p.rfind("in ", 0) == 0 ? model::Direction::In : model::Direction::Out;
      std::string rest = p.substr(p.find(' ') + 1);
      port.name = rest.substr(0, rest.find(':'));
      port.type = parse_type(rest.substr(rest.find(':') + 1));
      m.ports.push_back(port);
    }
    app.modules.push_back(m);
  }

  // Adds a connection; a non-empty script is written as monitors/<name>.lua, its digest
  // recorded in the model.
  model::Connection& connect(const std::string& name, const std::string& source,
                             const std::string& destination, const std::string& constraint,
                             const std::string& script = "",
                             model::ConnectionKind kind = model::ConnectionKind::Rule) {
    model::Connection c;
    c.name = name;
    c.source = source;
    c.destination = destination;
    c.kind = kind;
    std::string error;
    std::optional<Constraint> parsed = parse_constraint(constraint, &error);
    EXPECT_TRUE(parsed) << error;
    if (parsed) c.constraint = *parsed;
    if (!script.empty()) {
      c.monitor = "monitors/" + name + ".lua";
      c.monitor_sha256 = sha256_hex(script);  // as `arbc build` records it
      std::ofstream(dir + "/" + c.monitor) << script;
    }
    app.connections.push_back(c);
    return app.connections.back();
  }

  // Creates the runtime (failing the test on error) and collects its reports.
  std::unique_ptr<Runtime> start(RunOptions options = {}) {
    std::string error;
    auto rt = Runtime::create(app, dir, options, &error, registry);
    EXPECT_TRUE(rt) << error;
    if (!rt) return nullptr;
    rt->set_reporter([this](const std::string& line) { reports.push_back(line); });
    rt->start();
    return rt;
  }

  static Sink& sink(Runtime& rt, const std::string& name = "Sink") {
    return *dynamic_cast<Sink*>(rt.module(name));
  }

  // Publishes v from module.port at time t (by posting on the executor).
  static void publish_at(Runtime& rt, Nanos t, const std::string& module, const std::string& port,
                         Value v) {
    rt.executor().post(t, [&rt, module, port, v] { rt.publish(module, port, v); });
  }
  // The same at t seconds, to the nearest nanosecond as the module API takes them.
  static void publish_at(Runtime& rt, double t, const std::string& module, const std::string& port,
                         Value v) {
    publish_at(rt, nanos_from_seconds(t), module, port, std::move(v));
  }

  static const ConnectionStats& stats_of(const std::vector<ConnectionStats>& all,
                                         const std::string& name) {
    for (const ConnectionStats& s : all) {
      if (s.name == name) return s;
    }
    static ConnectionStats none;
    ADD_FAILURE() << "no connection " << name;
    return none;
  }

  model::App app;
  std::string dir;
  Registry registry;
  std::vector<std::string> reports;
};

// Publishes a random int every 0.1 s and a random flag every 0.2 or 0.6 s.
class Noisy : public Module {
 public:
  double tick_period() const override { return 0.1; }
  void start() override { flag(); }
  void tick() override { publish("x", Value(static_cast<int64_t>(rng()() % 100))); }
  void flag() {
    publish("f", Value(rng()() % 2 == 0));
    schedule(rng()() % 2 ? 0.2 : 0.6, [this] { flag(); });
  }
};

// Registers Noisy and builds the app around it that the trace and report tests run: Noisy,
// a Sink, and a feed `feed` setting event `e` (lifetime 0.4 s) from Noisy.f while the flag is
// true. The caller adds the rules on Noisy.x -> Sink.x.
inline void add_noisy_app(TestApp& t) {
  t.registry.add_module("Noisy", [] { return std::make_unique<Noisy>(); });
  t.module("Noisy", {"out x: int", "out f: bool"});
  t.module("Sink", {"in x: int"});
  t.connect("feed", "Noisy.f", "Sink.x", "false",
            "PortMonitor.accept = function(on)\n"
            "  if on then PortMonitor.setEvent('e', 0.4) else PortMonitor.unsetEvent('e') end\n"
            "  return true\n"
            "end\n",
            model::ConnectionKind::Feed);
}

}  // namespace arbc::testing
