// End to end through a real plugin: load_plugin, app dir loading, module checks, a run.
#include <gtest/gtest.h>

#include "runtime/app_loader.h"
#include "runtime/runtime.h"

namespace arbc {
namespace {

TEST(PluginTest, LoadsAPluginAndRunsTheAppToSuccess) {
  ASSERT_EQ(load_plugin(ARBC_TEST_PLUGIN), "");
  EXPECT_NE(Registry::global().find_module("Ticker"), nullptr);
  EXPECT_NE(Registry::global().find_environment("pingpong"), nullptr);
  // Loading it twice registers nothing new: said clearly.
  EXPECT_NE(load_plugin(ARBC_TEST_PLUGIN).find("registered no module"), std::string::npos);

  std::string dir = std::string(ARBC_SOURCE_DIR) + "/runtime/testdata/pingpong";
  AppDirLoad load = load_app_dir(dir);
  ASSERT_TRUE(load.ok) << (load.errors.empty() ? "" : load.errors[0]);
  EXPECT_TRUE(check_modules(load.app, "app.json").empty());
  std::string error;
  RunOptions o;
  o.duration = 60;
  auto rt = Runtime::create(load.app, dir, o, &error);
  ASSERT_TRUE(rt) << error;
  rt->run();
  EXPECT_EQ(rt->scenario(), "normal");
  EXPECT_EQ(rt->stop_reason(), "enough commands");
  ASSERT_TRUE(rt->environment());
  EXPECT_TRUE(rt->environment()->success()) << rt->environment()->summary();
  EXPECT_LT(rt->now(), 60);
}

TEST(PluginTest, MissingLibraryIsAClearError) {
  EXPECT_NE(load_plugin("/nonexistent/libnothing.so").find("cannot load plugin"),
            std::string::npos);
}

}  // namespace
}  // namespace arbc
