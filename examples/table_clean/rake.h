// The rake as PullObject drives it (the paper's tool use): take the rake from its rack, reach
// behind the object, pull it into hand reach, put the rake back, then report idle. A `pull`
// while a run is under way is ignored (as the paper's module does); a `cancel` sends the rake
// back early and is ignored while idle or already returning. The arm is shared: a pull while
// PickAndPlace is busy or holding is refused and counted as a conflict.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "examples/table_clean/geometry.h"

namespace arbc::table_clean {

class World;

enum class RakeState { Idle, Fetching, Reaching, Pulling, Returning };

class Rake {
 public:
  static constexpr double kFetchDuration = 1.0;  // seconds
  static constexpr double kReachDuration = 1.0;
  static constexpr double kPullDuration = 1.0;
  static constexpr double kReturnDuration = 1.0;

  explicit Rake(World& world) : world_(world) {}

  // Starts a raking run for the object nearest `pos` (within kGraspTolerance). Ignored while a
  // run is under way; refused with a conflict while the arm is busy or holding.
  void pull(const Vec3& pos, double now);
  // Aborts a run: the rake goes back to the rack, then the module reports idle.
  void cancel(double now);
  void update(double now);
  std::optional<double> next_deadline() const;

  // "e_pull_idle" while the rake is on its rack and nothing is under way.
  std::vector<std::string> status() const;
  RakeState state() const { return state_; }
  bool out() const { return state_ != RakeState::Idle; }
  int objects_pulled() const { return objects_pulled_; }
  int redundant_pulls() const { return redundant_pulls_; }
  int cancels_honoured() const { return cancels_honoured_; }
  int cancels_ignored() const { return cancels_ignored_; }

 private:
  void advance_phase();
  void start_phase(RakeState state, double duration);

  World& world_;
  RakeState state_ = RakeState::Idle;
  std::optional<int> target_;
  Vec3 target_pos_ = Vec3::Zero();
  double phase_end_ = 0;
  bool perturbed_once_ = false;
  int objects_pulled_ = 0;
  int redundant_pulls_ = 0;
  int cancels_honoured_ = 0;
  int cancels_ignored_ = 0;
};

std::string_view rake_state_name(RakeState state);

}  // namespace arbc::table_clean
