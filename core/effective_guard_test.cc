#include "core/effective_guard.h"

#include <gtest/gtest.h>

namespace arbc::model {
namespace {

Connection rule(std::string name, std::string guard) {
  Connection c;
  c.name = std::move(name);
  c.source = "S." + c.name;
  c.destination = "H.gaze";
  c.constraint = parse_constraint(guard).constraint;
  return c;
}

TEST(EffectiveGuardTest, AddsEventsSetOnEveryAcceptingPath) {
  App app;
  Connection track = rule("track", "true");
  track.sets = track.must_set = {"e_face_detected"};
  app.connections = {track, rule("search", "not e_face_detected")};
  EXPECT_EQ(effective_guard(app, "H.gaze", app.connections[0]).to_string(), "e_face_detected");
  EXPECT_EQ(effective_guard(app, "H.gaze", app.connections[1]).to_string(), "not e_face_detected");
}

TEST(EffectiveGuardTest, AnUnsetCountsOnlyWhenNoOtherConnectionSetsTheEvent) {
  App app;
  Connection a = rule("a", "x");
  a.unsets = a.must_unset = {"busy"};
  app.connections = {a, rule("b", "true")};
  EXPECT_EQ(effective_guard(app, "H.gaze", app.connections[0]).to_string(), "x and not busy");
  app.connections[1].sets = {"busy"};
  EXPECT_EQ(effective_guard(app, "H.gaze", app.connections[0]).to_string(), "x");
}

TEST(EffectiveGuardTest, ScriptRulesAreOpaque) {
  App app;
  Connection s = rule("s", "y");
  s.must_set = {"z"};
  s.opaque = true;
  app.connections = {s};
  EXPECT_EQ(effective_guard(app, "H.gaze", app.connections[0]).to_string(), "y");
}

}  // namespace
}  // namespace arbc::model
