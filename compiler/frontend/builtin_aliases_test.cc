#include "compiler/frontend/builtin_aliases.h"

#include <gtest/gtest.h>

#include "core/builtins.h"

namespace arbc::frontend {
namespace {

// The candidates sema passes: every builtin of the one table.
const std::vector<std::string> kNames = [] {
  std::vector<std::string> names;
  for (const BuiltinInfo& b : kBuiltins) names.emplace_back(b.name);
  return names;
}();

TEST(MeantBuiltin, TyposGoByEditDistance) {
  EXPECT_EQ(meant_builtin("lne", kNames, nullptr), "len");
  EXPECT_EQ(meant_builtin("nrom", kNames, nullptr), "norm");
  EXPECT_EQ(meant_builtin("sqrt", kNames, nullptr), std::nullopt);
}

TEST(MeantBuiltin, OtherLanguagesNamesForALength) {
  TypePtr list = Type::list(Type::scalar(Type::Kind::String));
  EXPECT_EQ(meant_builtin("length", kNames, list), "len");
  EXPECT_EQ(meant_builtin("size", kNames, list), "len");
  EXPECT_EQ(meant_builtin("count", kNames, nullptr), "len");
  EXPECT_EQ(meant_builtin("distance", kNames, nullptr), "dist");
  EXPECT_EQ(meant_builtin("magnitude", kNames, nullptr), "norm");
  // A vector's length is its norm; a typo of `length` counts as `length`.
  EXPECT_EQ(meant_builtin("length", kNames, Type::scalar(Type::Kind::Vec3)), "norm");
  EXPECT_EQ(meant_builtin("lenght", kNames, Type::scalar(Type::Kind::Vec3)), "norm");
  EXPECT_EQ(meant_builtin("lenght", kNames, list), "len");
  EXPECT_EQ(meant_builtin("sizes", kNames, list), "len");
  // Nothing close to a builtin or to another language's name.
  EXPECT_EQ(meant_builtin("average", kNames, list), std::nullopt);
}

}  // namespace
}  // namespace arbc::frontend
