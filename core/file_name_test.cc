#include "core/file_name.h"

#include <gtest/gtest.h>

#include <sstream>
#include <thread>
#include <vector>

#include "core/app_model.h"

namespace arbc::model {
namespace {

TEST(FileNameTest, EqualPathsShareOneStringAndCompareEqual) {
  std::string built = std::string("/robot/specs/") + "table_clean.spec";
  FileName a = built;
  FileName b = "/robot/specs/table_clean.spec";
  EXPECT_EQ(a, b);
  EXPECT_EQ(&a.str(), &b.str());  // interned: one copy per process
  EXPECT_EQ(a, std::string("/robot/specs/table_clean.spec"));
  EXPECT_NE(a, FileName("/robot/specs/other.spec"));
}

TEST(FileNameTest, NoFileIsEmptyAndEqualToAnEmptyPath) {
  FileName none;
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(none.str(), "");
  EXPECT_EQ(none, FileName(""));
  EXPECT_FALSE(FileName("a.spec").empty());
}

TEST(FileNameTest, OrdersByPathAndPrintsAsThePath) {
  EXPECT_LT(FileName("a.spec"), FileName("b.spec"));
  EXPECT_LT(FileName(), FileName("a.spec"));
  std::ostringstream out;
  out << FileName("x.spec") << ":" << 3;
  EXPECT_EQ(out.str(), "x.spec:3");
  EXPECT_EQ(FileName("x.spec") + ":3", "x.spec:3");
}

TEST(FileNameTest, CopyingALocationKeepsItsFile) {
  SourceLocation loc;
  loc.file = std::string("specs/a.spec");
  loc.line = 4;
  SourceLocation copy = loc;
  loc.file = "specs/b.spec";
  EXPECT_EQ(copy.file, "specs/a.spec");
  EXPECT_EQ(loc.file, "specs/b.spec");
}

// The language server builds locations on several threads (lsp/server_workers.cc).
TEST(FileNameTest, ThreadsInterningTheSamePathsAgree) {
  std::vector<const std::string*> seen(8);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < seen.size(); ++t) {
    threads.emplace_back([&seen, t] {
      for (int i = 0; i < 1000; ++i) FileName("threads/" + std::to_string(i) + ".spec");
      seen[t] = &FileName("threads/500.spec").str();
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (const std::string* s : seen) EXPECT_EQ(s, seen[0]);
}

}  // namespace
}  // namespace arbc::model
