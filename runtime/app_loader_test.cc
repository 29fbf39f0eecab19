#include "runtime/app_loader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/app_json.h"
#include "runtime/runtime_test_util.h"

namespace arbc {
namespace {

class Speak : public Module {
 public:
  Speak() { in("text", "string"); }
};
class Detector : public Module {
 public:
  Detector() { out("objects", "list<{pos: vec3, dist: float}>"); }
};

TEST(AppLoaderTest, ChecksModulesAndPortTypes) {
  testing::TestApp t;
  Registry r;
  r.add_module("Speak", [] { return std::make_unique<Speak>(); });
  r.add_module("Detector", [] { return std::make_unique<Detector>(); });
  t.module("Speak", {"in text: string"});
  t.module("Detector", {"out objects: list<{dist: float, pos: vec3}>"});
  EXPECT_TRUE(check_modules(t.app, "app.json", r).empty());

  t.app.modules.clear();
  t.module("Speak", {"in text: int", "in volume: float"});
  t.module("Detector", {"in objects: list<{dist: float, pos: vec3}>"});
  t.module("Arm", {"in cmd: string"});
  std::vector<std::string> errors = check_modules(t.app, "out/app.json", r);
  ASSERT_EQ(errors.size(), 4u);
  EXPECT_EQ(errors[0],
            "out/app.json: port Speak.text has type int in the app but the module declares "
            "string");
  EXPECT_NE(errors[1].find("port Speak.volume (in float) is not declared by the registered "
                           "module Speak"),
            std::string::npos);
  EXPECT_EQ(errors[2],
            "out/app.json: port Detector.objects is 'in' in the app but 'out' in the module");
  EXPECT_EQ(errors[3],
            "out/app.json: module 'Arm' is not registered; load the plugin that provides it "
            "with --plugin LIB (registered: Detector, Speak)");
}

TEST(AppLoaderTest, LoadsAnAppDirAndNamesMissingOrChangedMonitors) {
  testing::TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: int"});
  t.connect("c", "Src.x", "Sink.x", "true", "PortMonitor.accept = function(m) return true end\n");
  model::Connection& d = t.connect("d", "Src.x", "Sink.x", "true");
  d.monitor = "monitors/missing.lua";
  d.monitor_sha256 = std::string(64, '0');
  std::ofstream(t.dir + "/app.json") << model::to_app_json(t.app);
  std::string err;
  EXPECT_FALSE(load_app_dir(t.dir, &err));
  EXPECT_EQ(err, t.dir +
                     "/monitors/missing.lua: connection 'd' names this monitor, "
                     "but it cannot be read (rebuild the app with `arbc build`)");

  // A monitor edited after the build: its bytes no longer match app.json's digest.
  t.app.connections.pop_back();
  std::ofstream(t.dir + "/app.json") << model::to_app_json(t.app);
  err.clear();
  EXPECT_TRUE(load_app_dir(t.dir, &err)) << err;
  std::ofstream(t.dir + "/monitors/c.lua") << "PortMonitor.accept = function(m) return false end\n";
  EXPECT_FALSE(load_app_dir(t.dir, &err));
  EXPECT_EQ(err.find('\n'), std::string::npos) << err;  // one problem, one line
  EXPECT_EQ(err.rfind(t.dir + "/monitors/c.lua: this monitor of connection 'c' is "
                              "not the one `arbc build` wrote",
                      0),
            0u)
      << err;

  EXPECT_FALSE(load_app_dir(t.dir + "/nowhere", &err));
  EXPECT_NE(err.find("not a directory"), std::string::npos) << err;

  // The directory `arbc build -o OUT` was given, not the app directory OUT/APP it wrote.
  std::filesystem::create_directories(t.dir + "/out/app");
  std::filesystem::copy_file(t.dir + "/app.json", t.dir + "/out/app/app.json");
  EXPECT_FALSE(load_app_dir(t.dir + "/out", &err));
  EXPECT_NE(err.find("It holds " + t.dir + "/out/app."), std::string::npos) << err;

  std::ofstream(t.dir + "/app.json") << "{\"schema_version\": ";
  EXPECT_FALSE(load_app_dir(t.dir, &err));
  EXPECT_NE(err.find("app.json"), std::string::npos) << err;
}

TEST(AppLoaderTest, TypeMismatchWithoutUpdateIsAnError) {
  testing::TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: string"});
  t.connect("c", "Src.x", "Sink.x", "true");
  std::string error;
  EXPECT_FALSE(Runtime::create(t.app, t.dir, {}, &error, t.registry));
  EXPECT_EQ(error,
            "the app: connection 'c': Src.x carries int but Sink.x takes string, and no monitor "
            "update converts it");
  // An error about the model's content names the file it came from.
  RunOptions o;
  o.app_file = "out/demo/app.json";
  EXPECT_FALSE(Runtime::create(t.app, t.dir, o, &error, t.registry));
  EXPECT_EQ(error.rfind("out/demo/app.json: connection 'c': Src.x carries int", 0), 0u) << error;
}

// Errors about something else than the model's content name that, not the model's file: a
// plugin's module, a monitor file, the trace file.
TEST(AppLoaderTest, OtherCreateErrorsDoNotNameTheAppFile) {
  RunOptions o;
  o.app_file = "out/demo/app.json";
  std::string error;
  testing::TestApp plugin;
  plugin.registry.add_module("Broken", []() -> std::unique_ptr<Module> { return nullptr; });
  plugin.module("Broken", {"out x: int"});
  EXPECT_FALSE(Runtime::create(plugin.app, plugin.dir, o, &error, plugin.registry));
  EXPECT_EQ(error, "module 'Broken' could not be created: its factory returned no object");
  testing::TestApp monitor;
  monitor.module("Src", {"out x: int"});
  monitor.module("Sink", {"in x: int"});
  monitor.connect("c", "Src.x", "Sink.x", "true", "this is not Lua\n");
  EXPECT_FALSE(Runtime::create(monitor.app, monitor.dir, o, &error, monitor.registry));
  EXPECT_EQ(error.rfind("connection 'c': its monitor script failed to load: " + monitor.dir +
                            "/monitors/c.lua:1:",
                        0),
            0u)
      << error;
  testing::TestApp trace;
  o.trace_path = trace.dir + "/no/such/dir/trace.jsonl";
  EXPECT_FALSE(Runtime::create(trace.app, trace.dir, o, &error, trace.registry));
  EXPECT_EQ(error.rfind("cannot write trace file " + o.trace_path, 0), 0u) << error;
}

}  // namespace
}  // namespace arbc
