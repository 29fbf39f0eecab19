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

// `by priority`: the activity event is set by the runtime on delivery, not by the monitor
// before the decision; the guard includes it all the same, also for a script rule.
TEST(EffectiveGuardTest, IncludesTheActivityEventTheRuntimeSetsOnDelivery) {
  App app;
  Connection track = rule("track", "e_idle");
  track.sets = {"act_track"};
  track.activity_event = "act_track";
  Connection search = rule("search", "e_idle and not act_track");
  app.connections = {track, search};
  EXPECT_EQ(effective_guard(app, "H.gaze", app.connections[0]).to_string(), "e_idle and act_track");
  EXPECT_EQ(effective_guard(app, "H.gaze", app.connections[1]).to_string(),
            "e_idle and not act_track");
  app.connections[0].opaque = true;
  EXPECT_EQ(effective_guard(app, "H.gaze", app.connections[0]).to_string(), "e_idle and act_track");
}

}  // namespace
}  // namespace arbc::model
