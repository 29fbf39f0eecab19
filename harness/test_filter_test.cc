// harness/test_filter.h: --filter is a glob over the whole name, and matching nothing says so.
#include "harness/test_filter.h"

#include <gtest/gtest.h>

namespace arbc::harness {
namespace {

TEST(TestFilterTest, AGlobMatchesTheWholeName) {
  EXPECT_TRUE(filter_matches("*", "joystick wins"));
  EXPECT_TRUE(filter_matches("joystick*", "joystick wins"));
  EXPECT_FALSE(filter_matches("joystick", "joystick wins"));
}

TEST(TestFilterTest, MatchingNothingSuggestsThePartOrListsTheTests) {
  std::string part = filter_matched_none("joystick", {"joystick wins", "bumper"});
  EXPECT_EQ(part,
            "--filter 'joystick' matches none of the 2 tests (a glob over the whole name); did "
            "you mean --filter '*joystick*'?");
  std::string list = filter_matched_none("nav", {"bumper"});
  EXPECT_EQ(list,
            "--filter 'nav' matches none of the 1 test (a glob over the whole name); the tests "
            "are:\n  bumper");
}

}  // namespace
}  // namespace arbc::harness
