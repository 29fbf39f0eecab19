// The search_and_track app's environment (the paper's section "Port Arbitrator"): nobody is
// there at first, a person appears, later leaves. The head should find the face by looking
// around, track it while it is seen, and resume looking around about one second (the spec's
// e_face_detected lifetime) after the face is gone.
#include <cstdio>

#include "examples/table_clean/modules/world_environment.h"

namespace arbc::table_clean {
namespace {

class SearchAndTrackEnvironment : public WorldEnvironment {
 public:
  static constexpr double kAppear = 2.0;  // seconds
  static constexpr double kLeave = 12.0;
  static constexpr double kCheckPeriod = 0.1;
  // Searching must resume after the hold, and within the hold plus a LookAround period (0.5 s)
  // and some slack.
  static constexpr double kMinResume = 1.0;
  static constexpr double kMaxResume = 2.0;

  std::vector<std::string> scenarios() const override { return {"appear_and_leave"}; }

  void setup(arbc::EnvironmentContext& ctx) override {
    create_world(ctx);
    World* world = world_.get();
    world->person().set_present(false);
    world->schedule(kAppear, [world] { world->person().set_present(true); });
    world->schedule(kLeave, [this, world] {
      world->person().set_present(false);
      gaps_before_leaving_ = world->referee().search_resume_gaps().size();
    });
    check();
  }

  void finish() override { end_time_ = ctx_->now(); }

  std::string summary() const override {
    const GazeReferee& r = world_->referee();
    std::string out;
    char line[160];
    auto add = [&](const char* fmt, auto... args) {
      std::snprintf(line, sizeof line, fmt, args...);
      out += line;
      out += '\n';
    };
    add("scenario appear_and_leave, seed %llu", static_cast<unsigned long long>(ctx_->seed()));
    add("person present from %.2f s to %.2f s", kAppear, kLeave);
    add("simulated time: %.2f s", end_time_);
    add("head: %d face targets, %d search targets", r.face_targets(), r.search_targets());
    if (r.first_face_target() >= 0) {
      add("face found %.2f s after the person appeared", r.first_face_target() - kAppear);
    } else {
      add("face %s", "never found");
    }
    if (resume_gap_ >= 0) add("search resumed %.2f s after the last face target", resume_gap_);
    add("conflicts: %d", world_->conflicts().total());
    for (const auto& [name, count] : world_->conflicts().by_name()) {
      add("  %s: %d", name.c_str(), count);
    }
    add("result: %s", success() ? "found, tracked, resumed searching" : "FAILED");
    return out;
  }

  bool success() const override {
    const GazeReferee& r = world_->referee();
    return r.first_face_target() >= kAppear && r.first_face_target() < kLeave &&
           resume_gap_ >= kMinResume && resume_gap_ <= kMaxResume &&
           world_->conflicts().total() == 0;
  }

 private:
  // Polls the referee: once searching resumed after the person left, the run has shown all.
  void check() {
    world_->advance_to(ctx_->now());
    const GazeReferee& r = world_->referee();
    if (ctx_->now() > kLeave && r.search_resume_gaps().size() > gaps_before_leaving_) {
      resume_gap_ = r.search_resume_gaps().back();
      ctx_->request_stop("searching again after the face left");
      return;
    }
    ctx_->schedule(kCheckPeriod, [this] { check(); });
  }

  double resume_gap_ = -1;
  size_t gaps_before_leaving_ = 0;
};

ARBC_REGISTER_ENVIRONMENT(SearchAndTrackEnvironment, "search_and_track");

}  // namespace
}  // namespace arbc::table_clean
