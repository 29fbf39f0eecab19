#include "compiler/codegen/write_artifacts.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace arbc::codegen {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ino_t inode(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::stat(p.c_str(), &st), 0) << p;
  return st.st_ino;
}

class WriteArtifacts : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = fs::temp_directory_path() /
           ("arbc_write_artifacts_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(out_);
  }
  void TearDown() override { fs::remove_all(out_); }
  fs::path out_;
};

TEST_F(WriteArtifacts, RebuildKeepsUnchangedFilesAndReplacesTheRest) {
  std::string error;
  ASSERT_TRUE(write_artifacts(out_, "app",
                              {{"app.json", "{}\n"},
                               {"monitors/a.lua", "-- a\n"},
                               {"monitors/b.lua", "-- b\n"},
                               {"monitors/gone.lua", "-- gone\n"}},
                              &error))
      << error;
  fs::path app = out_ / "app";
  ino_t a_before = inode(app / "monitors/a.lua");
  ino_t b_before = inode(app / "monitors/b.lua");

  ASSERT_TRUE(write_artifacts(
      out_, "app",
      {{"app.json", "{}\n"}, {"monitors/a.lua", "-- a\n"}, {"monitors/b.lua", "-- b, changed\n"}},
      &error))
      << error;
  EXPECT_EQ(inode(app / "monitors/a.lua"), a_before);  // the same file, linked
  EXPECT_EQ(read(app / "monitors/a.lua"), "-- a\n");
  EXPECT_EQ(read(app / "monitors/b.lua"), "-- b, changed\n");
  EXPECT_NE(inode(app / "monitors/b.lua"), b_before);
  EXPECT_FALSE(fs::exists(app / "monitors/gone.lua"));         // no rule, no monitor
  EXPECT_EQ(fs::hard_link_count(app / "monitors/a.lua"), 1u);  // the old build is gone
  EXPECT_FALSE(fs::exists(out_ / ".app.arbc-tmp"));
}

TEST_F(WriteArtifacts, RefusesToReplaceADirectoryThatIsNotABuild) {
  fs::create_directories(out_ / "app");
  std::ofstream(out_ / "app" / "notes.txt") << "mine\n";
  std::string error;
  EXPECT_FALSE(write_artifacts(out_, "app", {{"app.json", "{}\n"}}, &error));
  EXPECT_NE(error.find("refusing to replace"), std::string::npos) << error;
  EXPECT_EQ(read(out_ / "app" / "notes.txt"), "mine\n");
}

TEST_F(WriteArtifacts, AFileThatIsNotRegularInThePreviousBuildIsWrittenNotLinked) {
  std::string error;
  ASSERT_TRUE(write_artifacts(out_, "app", {{"app.json", "{}\n"}, {"monitors/a.lua", ""}}, &error))
      << error;
  fs::path app = out_ / "app";
  fs::remove(app / "monitors/a.lua");
  ASSERT_EQ(::mkfifo((app / "monitors/a.lua").c_str(), 0600), 0);  // must not block the build
  fs::create_directory(app / "monitors/b.lua");
  ASSERT_TRUE(write_artifacts(
      out_, "app", {{"app.json", "{}\n"}, {"monitors/a.lua", ""}, {"monitors/b.lua", ""}}, &error))
      << error;
  EXPECT_TRUE(fs::is_regular_file(app / "monitors/a.lua"));
  EXPECT_TRUE(fs::is_regular_file(app / "monitors/b.lua"));
  EXPECT_FALSE(fs::exists(out_ / ".app.arbc-tmp"));
}

TEST_F(WriteArtifacts, TheOldBuildIsRemovedWithoutFollowingLinks) {
  fs::path elsewhere = out_ / "elsewhere";
  fs::create_directories(elsewhere);
  std::ofstream(elsewhere / "keep.txt") << "keep\n";
  std::string error;
  ASSERT_TRUE(write_artifacts(out_, "app", {{"app.json", "{}\n"}, {"a/b/c.lua", "c\n"}}, &error))
      << error;
  fs::create_directory_symlink(elsewhere, out_ / "app" / "a" / "link");
  ASSERT_TRUE(write_artifacts(out_, "app", {{"app.json", "{}\n"}}, &error)) << error;
  EXPECT_FALSE(fs::exists(out_ / "app" / "a"));
  EXPECT_EQ(read(elsewhere / "keep.txt"), "keep\n");
  EXPECT_FALSE(fs::exists(out_ / ".app.arbc-tmp"));
}

TEST_F(WriteArtifacts, ALargeBuildIsWrittenOnTwoThreadsWithTheSameResult) {
  auto build = [](int generation) {
    std::vector<OutputFile> files = {{"app.json", "{}\n"}};
    for (int i = 0; i < 1500; ++i) {
      std::string content = "-- monitor " + std::to_string(i) + "\n";
      if (i % 3 == 0) content += "-- build " + std::to_string(generation) + "\n";
      files.push_back({"monitors/m" + std::to_string(i) + ".lua", content});
    }
    return files;
  };
  std::string error;
  ASSERT_TRUE(write_artifacts(out_, "app", build(1), &error)) << error;
  fs::path app = out_ / "app";
  std::vector<ino_t> before;
  for (int i = 0; i < 1500; ++i)
    before.push_back(inode(app / ("monitors/m" + std::to_string(i) + ".lua")));
  std::vector<OutputFile> second = build(2);
  ASSERT_TRUE(write_artifacts(out_, "app", second, &error)) << error;
  for (int i = 0; i < 1500; ++i) {
    fs::path f = app / ("monitors/m" + std::to_string(i) + ".lua");
    EXPECT_EQ(read(f), second[i + 1].content) << f;
    EXPECT_EQ(inode(f) == before[i], i % 3 != 0) << f;  // unchanged files are linked
  }
  EXPECT_FALSE(fs::exists(out_ / ".app.arbc-tmp"));
}

}  // namespace
}  // namespace arbc::codegen
