#include "runtime/app_loader.h"

#include <gtest/gtest.h>

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
  AppDirLoad load = load_app_dir(t.dir);
  EXPECT_FALSE(load.ok);
  ASSERT_EQ(load.errors.size(), 1u);
  EXPECT_EQ(load.errors[0], t.dir +
                                "/monitors/missing.lua: connection 'd' names this monitor, "
                                "but it cannot be read (rebuild the app with `arbc build`)");

  // A monitor edited after the build: its bytes no longer match app.json's digest.
  t.app.connections.pop_back();
  std::ofstream(t.dir + "/app.json") << model::to_app_json(t.app);
  EXPECT_TRUE(load_app_dir(t.dir).ok);
  std::ofstream(t.dir + "/monitors/c.lua") << "PortMonitor.accept = function(m) return false end\n";
  AppDirLoad edited = load_app_dir(t.dir);
  ASSERT_EQ(edited.errors.size(), 1u);
  EXPECT_EQ(edited.errors[0].rfind(t.dir + "/monitors/c.lua: this monitor of connection 'c' is "
                                           "not the one `arbc build` wrote",
                                   0),
            0u)
      << edited.errors[0];

  AppDirLoad none = load_app_dir(t.dir + "/nowhere");
  ASSERT_EQ(none.errors.size(), 1u);
  EXPECT_NE(none.errors[0].find("not a directory"), std::string::npos);

  std::ofstream(t.dir + "/app.json") << "{\"schema_version\": ";
  AppDirLoad broken = load_app_dir(t.dir);
  ASSERT_EQ(broken.errors.size(), 1u);
  EXPECT_NE(broken.errors[0].find("app.json"), std::string::npos);
}

TEST(AppLoaderTest, TypeMismatchWithoutUpdateIsAnError) {
  testing::TestApp t;
  t.module("Src", {"out x: int"});
  t.module("Sink", {"in x: string"});
  t.connect("c", "Src.x", "Sink.x", "true");
  std::string error;
  EXPECT_FALSE(Runtime::create(t.app, t.dir, {}, &error, t.registry));
  EXPECT_EQ(error,
            "connection 'c': Src.x carries int but Sink.x takes string, and no monitor update "
            "converts it");
}

}  // namespace
}  // namespace arbc
