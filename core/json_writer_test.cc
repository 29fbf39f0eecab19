#include "core/json_writer.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace arbc {
namespace {

using Ordered = nlohmann::ordered_json;

// The writer promises nlohmann's dump(2) layout, so app.json keeps its bytes whichever wrote
// it; nlohmann itself is the reference.
TEST(JsonWriter, MatchesNlohmannPrettyLayout) {
  JsonWriter w;
  w.begin_object();
  w.key("name");
  w.value("table \"clean\"\n");
  w.key("empty_list");
  w.begin_array();
  w.end_array();
  w.key("empty_object");
  w.begin_object();
  w.end_object();
  w.key("numbers");
  w.begin_array();
  w.value(3);
  w.value(0.5);
  w.value(2.0);
  w.null();
  w.value(true);
  w.end_array();
  w.key("nested");
  w.begin_array();
  w.begin_array();
  w.value(1);
  w.value(2);
  w.end_array();
  w.begin_object();
  w.key("strings");
  w.value(std::vector<std::string>{"a", "b\\c"});
  w.end_object();
  w.end_array();
  w.end_object();

  Ordered expected;
  expected["name"] = "table \"clean\"\n";
  expected["empty_list"] = Ordered::array();
  expected["empty_object"] = Ordered::object();
  expected["numbers"] = Ordered::array({3, 0.5, 2.0, nullptr, true});
  Ordered inner;
  inner["strings"] = {"a", "b\\c"};
  expected["nested"] = Ordered::array({Ordered::array({1, 2}), inner});
  EXPECT_EQ(w.text(), expected.dump(2));
}

TEST(JsonWriter, TopLevelScalarHasNoIndent) {
  JsonWriter w;
  w.value(int64_t{-7});
  EXPECT_EQ(w.text(), "-7");
}

}  // namespace
}  // namespace arbc
