#include "compiler/frontend/unit_words.h"

#include <gtest/gtest.h>

namespace arbc::frontend {
namespace {

TEST(DurationUnit, MapsTimeSpellingsToTheLanguagesUnits) {
  EXPECT_EQ(duration_unit("sec"), "s");
  EXPECT_EQ(duration_unit("seconds"), "s");
  EXPECT_EQ(duration_unit("msec"), "ms");
  EXPECT_EQ(duration_unit("mins"), "min");
  // Lengths and a bare `m` (metres or minutes?) are not time units.
  EXPECT_EQ(duration_unit("m"), std::nullopt);
  EXPECT_EQ(duration_unit("cm"), std::nullopt);
  EXPECT_EQ(duration_unit(""), std::nullopt);
}

TEST(SplitNumberSuffix, SplitsAtTheFirstLetter) {
  EXPECT_EQ(split_number_suffix("0.5sec"), std::make_pair(std::string("0.5"), std::string("sec")));
  EXPECT_EQ(split_number_suffix("40cm"), std::make_pair(std::string("40"), std::string("cm")));
  EXPECT_EQ(split_number_suffix("12"), std::make_pair(std::string("12"), std::string("")));
}

}  // namespace
}  // namespace arbc::frontend
