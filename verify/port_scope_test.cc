#include "verify/port_scope.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "verify/test_models.h"

namespace arbc::verify {
namespace {

using ::testing::ElementsAre;

TEST(PortScope, EffectiveGuardAddsMustSetEvents) {
  model::App app = testing::search_and_track_model();
  std::string error;
  std::optional<PortScope> scope = build_port_scope(app, app.arbitrated_ports[0], &error);
  ASSERT_TRUE(scope) << error;
  ASSERT_EQ(scope->rules.size(), 2u);
  EXPECT_EQ(scope->rules[0].effective_guard.to_string(), "e_face_detected");
  EXPECT_EQ(scope->rules[1].effective_guard.to_string(), "not e_face_detected");
  EXPECT_THAT(scope->events, ElementsAre("e_face_detected"));
}

TEST(PortScope, OpaqueRulesKeepTheirConstraint) {
  model::App app = testing::search_and_track_model();
  testing::connection(app, "track").opaque = true;
  std::string error;
  std::optional<PortScope> scope = build_port_scope(app, app.arbitrated_ports[0], &error);
  ASSERT_TRUE(scope) << error;
  EXPECT_EQ(scope->rules[0].effective_guard.to_string(), "true");
}

TEST(PortScope, AtMostOneIsPairwise) {
  EXPECT_EQ(at_most_one({"a", "b", "c"}).to_string(),
            "not (a and b) and not (a and c) and not (b and c)");
  EXPECT_EQ(at_most_one({"a"}).to_string(), "true");
}

}  // namespace
}  // namespace arbc::verify
