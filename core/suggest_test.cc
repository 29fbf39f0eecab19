#include "core/suggest.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("e_taken", "e_taken"), 0u);
  EXPECT_EQ(edit_distance("e_tken", "e_taken"), 1u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(EditDistance, CountsASwapOfAdjacentCharactersAsOneEdit) {
  EXPECT_EQ(edit_distance("lne", "len"), 1u);
  EXPECT_EQ(edit_distance("vce3", "vec3"), 1u);
  EXPECT_EQ(edit_distance("e_arm_idel", "e_arm_idle"), 1u);
  EXPECT_EQ(edit_distance("ab", "ba"), 1u);
  // Optimal string alignment: "ca" -> "ac" -> "abc" is not one swap then one insertion
  // inside the swapped pair, so three edits.
  EXPECT_EQ(edit_distance("ca", "abc"), 3u);
}

TEST(ClosestName, SuggestsOnlyPlausibleTypos) {
  std::vector<std::string> events = {"e_taken", "e_arm_idle", "e_pull_idle"};
  EXPECT_EQ(closest_name("e_tken", events), "e_taken");
  EXPECT_EQ(closest_name("e_arm_idel", events), "e_arm_idle");
  EXPECT_EQ(closest_name("completely_different", events), std::nullopt);
  // Short names allow a single edit only.
  EXPECT_EQ(closest_name("ab", {"xy"}), std::nullopt);
  EXPECT_EQ(closest_name("ab", {"abc"}), "abc");
  // A swapped pair is one edit, so even short names get it (`lne` for `len`).
  EXPECT_EQ(closest_name("lne", {"len", "min", "max"}), "len");
  EXPECT_EQ(closest_name("cdm", {"cmd", "status"}), "cmd");
  // The exact name is never suggested to itself.
  EXPECT_EQ(closest_name("e_taken", {"e_taken"}), std::nullopt);
}

}  // namespace
}  // namespace arbc
