#include "core/monitor_digests.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/sha256.h"

namespace arbc::model {
namespace {

namespace fs = std::filesystem;

// An app directory with one monitor whose digest is recorded, as `arbc build` writes it.
struct Dir {
  Dir() {
    path = (fs::temp_directory_path() / ("arbc_digests_" + std::to_string(getpid()))).string();
    fs::remove_all(path);
    fs::create_directories(path + "/monitors");
    std::ofstream(path + "/monitors/m.lua") << kScript;
    Connection c;
    c.name = "take";
    c.monitor = "monitors/m.lua";
    c.monitor_sha256 = sha256_hex(kScript);
    app.connections.push_back(c);
  }
  ~Dir() { fs::remove_all(path); }
  static constexpr const char* kScript = "PortMonitor.accept = function(m) return true end\n";
  std::string path;
  App app;
};

TEST(MonitorDigestsTest, TheBytesAsBuiltPass) {
  Dir d;
  EXPECT_TRUE(check_monitor_files(d.app, d.path).empty());
}

TEST(MonitorDigestsTest, AnEditedOrMissingMonitorIsNamed) {
  Dir d;
  std::ofstream(d.path + "/monitors/m.lua", std::ios::app) << " ";  // one byte more
  std::vector<std::string> errors = check_monitor_files(d.app, d.path);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].rfind(d.path + "/monitors/m.lua: this monitor of connection 'take' is not "
                                     "the one `arbc build` wrote",
                            0),
            0u)
      << errors[0];
  EXPECT_NE(errors[0].find("rebuild the app with `arbc build`"), std::string::npos);
  fs::remove(d.path + "/monitors/m.lua");
  errors = check_monitor_files(d.app, d.path);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("cannot be read"), std::string::npos) << errors[0];
}

TEST(MonitorDigestsTest, AModelBuiltInCodeHasNoDigestToCheck) {
  Dir d;
  d.app.connections[0].monitor_sha256.clear();
  std::ofstream(d.path + "/monitors/m.lua") << "anything";
  EXPECT_TRUE(check_monitor_files(d.app, d.path).empty());
}

}  // namespace
}  // namespace arbc::model
