#include "core/artifact_path.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

TEST(ArtifactPathTest, RelativePathsAreKeptAsGiven) {
  EXPECT_EQ(artifact_path("specs/table_clean.spec", "/home/me/arbc"), "specs/table_clean.spec");
  EXPECT_EQ(artifact_path("../other/a.spec", "/home/me/arbc"), "../other/a.spec");
  EXPECT_EQ(artifact_path("", "/home/me"), "");
}

TEST(ArtifactPathTest, AnAbsolutePathUnderTheWorkingDirectoryBecomesRelativeToIt) {
  EXPECT_EQ(artifact_path("/home/me/arbc/specs/t.spec", "/home/me/arbc"), "specs/t.spec");
  EXPECT_EQ(artifact_path("/home/me/arbc/specs/t.spec", "/home/me/arbc/"), "specs/t.spec");
  EXPECT_EQ(artifact_path("/home/me/arbc/./specs/../specs/t.spec", "/home/me/arbc"),
            "specs/t.spec");
}

TEST(ArtifactPathTest, AnAbsolutePathElsewhereIsReducedToItsFileName) {
  EXPECT_EQ(artifact_path("/tmp/build-42/t.spec", "/home/me/arbc"), "t.spec");
  EXPECT_EQ(artifact_path("/home/me/arbcx/t.spec", "/home/me/arbc"), "t.spec");  // not a prefix
  EXPECT_EQ(artifact_path("/home/me/arbc", "/home/me/arbc"), "arbc");
}

TEST(ArtifactPathTest, TheProcessWorkingDirectoryIsTheDefault) {
  EXPECT_EQ(artifact_path("/nowhere-arbc-test/dir/t.spec"), "t.spec");
  EXPECT_EQ(artifact_path("specs/t.spec"), "specs/t.spec");
}

}  // namespace
}  // namespace arbc
