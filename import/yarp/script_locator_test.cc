#include "import/yarp/script_locator.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace arbc::yarp {
namespace {

namespace fs = std::filesystem;

class ScriptLocator : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test and process: ctest runs this program's tests in parallel.
    root_ = fs::path(::testing::TempDir()) /
            ("arbc_locator_" +
             std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
             std::to_string(getpid()));
    fs::remove_all(root_);
    unsetenv("YARP_DATA_HOME");
    unsetenv("YARP_DATA_DIRS");
  }
  void TearDown() override { fs::remove_all(root_); }
  std::string touch(const fs::path& relative) {
    fs::path p = root_ / relative;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "-- monitor\n";
    return p.lexically_normal().generic_string();
  }
  fs::path root_;
};

TEST_F(ScriptLocator, SearchPathsComeBeforeTheXmlsFolder) {
  std::string xml = touch("app/app.xml");
  touch("app/ball.lua");
  std::string mine = touch("mine/ball.lua");
  ScriptLookup l = locate_script("ball", "", xml, {(root_ / "mine").string()});
  ASSERT_TRUE(l.found);
  EXPECT_EQ(*l.found, mine);
  EXPECT_EQ(l.tried.size(), 2u);  // mine/ball, mine/ball.lua
}

TEST_F(ScriptLocator, AContextIsAFolderUnderContexts) {
  std::string xml = touch("app/app.xml");
  touch("app/face.lua");
  std::string in_context = touch("app/contexts/faces/face.lua");
  ScriptLookup l = locate_script("face", "faces", xml, {});
  ASSERT_TRUE(l.found);
  EXPECT_EQ(*l.found, in_context);
}

TEST_F(ScriptLocator, YarpDataFoldersComeLast) {
  std::string xml = touch("app/app.xml");
  std::string data = touch("data2/contexts/c/m.lua");
  setenv("YARP_DATA_DIRS", ((root_ / "data1").string() + ":" + (root_ / "data2").string()).c_str(),
         1);
  ScriptLookup l = locate_script("m", "c", xml, {});
  ASSERT_TRUE(l.found);
  EXPECT_EQ(*l.found, data);
  unsetenv("YARP_DATA_DIRS");
}

TEST_F(ScriptLocator, NotFoundListsWhatWasTried) {
  std::string xml = touch("app/app.xml");
  ScriptLookup l = locate_script("x", "ctx", xml, {});
  EXPECT_FALSE(l.found);
  ASSERT_EQ(l.tried.size(), 4u);
  EXPECT_NE(l.tried[0].find("app/contexts/ctx/x"), std::string::npos);
  EXPECT_NE(l.tried[3].find("app/x.lua"), std::string::npos);
}

}  // namespace
}  // namespace arbc::yarp
