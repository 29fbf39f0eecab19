// End to end through a real plugin: load_plugin, app dir loading, module checks, a run.
#include <gtest/gtest.h>

#include "runtime/app_loader.h"
#include "runtime/runtime.h"
#include "tests/support/tree_paths.h"

namespace arbc {
namespace {

TEST(PluginTest, LoadsAPluginAndRunsTheAppToSuccess) {
  std::string err;
  ASSERT_TRUE(load_plugin(ARBC_TEST_PLUGIN, &err)) << err;
  EXPECT_NE(Registry::global().find_module("Ticker"), nullptr);
  EXPECT_NE(Registry::global().find_environment("pingpong"), nullptr);
  // Loading it twice registers nothing new: said clearly.
  EXPECT_FALSE(load_plugin(ARBC_TEST_PLUGIN, &err));
  EXPECT_NE(err.find("registered no module"), std::string::npos) << err;

  std::string dir = arbc::testing::source_dir() + "/runtime/testdata/pingpong";
  std::string error;
  std::optional<model::App> app = load_app_dir(dir, &error);
  ASSERT_TRUE(app) << error;
  EXPECT_TRUE(check_modules(*app, "app.json").empty());
  RunOptions o;
  o.duration = 60;
  auto rt = Runtime::create(*app, dir, o, &error);
  ASSERT_TRUE(rt) << error;
  rt->run();
  EXPECT_EQ(rt->scenario(), "normal");
  EXPECT_EQ(rt->stop_reason(), "enough commands");
  ASSERT_TRUE(rt->environment());
  EXPECT_TRUE(rt->environment()->success()) << rt->environment()->summary();
  EXPECT_LT(rt->now(), std::chrono::seconds(60));
}

TEST(PluginTest, MissingLibraryIsAClearError) {
  std::string err;
  EXPECT_FALSE(load_plugin("/nonexistent/libnothing.so", &err));
  EXPECT_NE(err.find("cannot load plugin"), std::string::npos) << err;
}

}  // namespace
}  // namespace arbc
