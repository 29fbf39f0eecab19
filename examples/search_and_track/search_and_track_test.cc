// The search-and-track app on the embedded runtime with the paper's monitors (C1: track sets
// e_face_detected for 1 s; C2: search when not e_face_detected): the head finds the face,
// tracks it, and looks around again about a second after the person left.
#include <gtest/gtest.h>

#include <cstdio>

#include "examples/table_clean/modules/world_environment.h"
#include "runtime/runtime.h"

namespace arbc::table_clean {

using namespace std::chrono_literals;
namespace {

model::App paper_search_and_track(const std::string& search_constraint) {
  model::App app;
  app.name = "search_and_track";
  auto port = [](std::string name, model::Direction dir, const char* type) {
    model::Port p;
    p.name = std::move(name);
    p.direction = dir;
    p.type = parse_type(type);
    return p;
  };
  app.modules.push_back({"FaceDetector",
                         "",
                         {port("face", model::Direction::Out, "{pos: vec3, certainty: float}")},
                         {}});
  app.modules.push_back({"LookAround", "", {port("gaze", model::Direction::Out, "vec3")}, {}});
  app.modules.push_back({"HeadControl", "", {port("gaze", model::Direction::In, "vec3")}, {}});
  model::Event e;
  e.name = "e_face_detected";
  e.lifetime = 1s;
  app.events.push_back(e);
  model::Connection track;
  track.name = "track";
  track.source = "FaceDetector.face";
  track.destination = "HeadControl.gaze";
  track.constraint = Constraint::constant(true);
  track.monitor = "paper_monitors/track.lua";
  model::Connection search;
  search.name = "search";
  search.source = "LookAround.gaze";
  search.destination = "HeadControl.gaze";
  search.constraint = parse_constraint(search_constraint).constraint;
  app.connections = {track, search};
  model::ArbitratedPort head;
  head.port = "HeadControl.gaze";
  head.rules = {"track", "search"};
  app.arbitrated_ports = {head};
  return app;
}

struct Outcome {
  bool success = false;
  std::string summary;
};

Outcome run(const model::App& app, uint64_t seed) {
  RunOptions options;
  options.seed = seed;
  options.duration = 60;
  std::string error;
  auto runtime = Runtime::create(app, ARBC_SEARCH_AND_TRACK_DIR, options, &error);
  EXPECT_TRUE(runtime) << error;
  if (!runtime) return {};
  runtime->set_reporter([](const std::string&) {});
  runtime->run();
  return {runtime->environment()->success(), runtime->environment()->summary()};
}

TEST(SearchAndTrack, FindsTracksAndResumesSearchingAboutASecondAfterTheFaceIsGone) {
  const model::App app = paper_search_and_track("not e_face_detected");
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Outcome out = run(app, seed);
    EXPECT_TRUE(out.success) << out.summary;
    if (seed == 1) std::printf("%s", out.summary.c_str());
  }
}

TEST(SearchAndTrack, SearchingRegardlessOfTheFaceShowsAsConflicts) {
  const Outcome out = run(paper_search_and_track("true"), 1);
  EXPECT_FALSE(out.success);
  EXPECT_NE(out.summary.find("search_during_face_hold"), std::string::npos) << out.summary;
}

}  // namespace
}  // namespace arbc::table_clean
