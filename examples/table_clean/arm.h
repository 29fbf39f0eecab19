// The arm as PickAndPlace drives it: `take` grasps the object at a position, `put` releases the
// held object at a position (the bucket). Both take time. Misuse is refused and counted as a
// conflict (conflicts.h); the arm is shared with the rake, so a take while the rake is out is
// one too.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "examples/table_clean/geometry.h"

namespace arbc::table_clean {

class World;

enum class ArmState { Idle, Taking, Putting };

class Arm {
 public:
  static constexpr double kTakeDuration = 1.2;  // seconds
  static constexpr double kPutDuration = 1.2;
  // A put releases into the bucket when aimed this close to it; elsewhere the object lands on
  // the table below the release point.
  static constexpr double kBucketRadius = 0.10;

  explicit Arm(World& world) : world_(world) {}

  // Starts grasping the object nearest `pos` (within kGraspTolerance and hand reach). With no
  // such object the arm still moves and comes back empty. Refused, with a conflict counted,
  // while holding, while busy or while the rake is out.
  void take(const Vec3& pos, double now);
  // Starts carrying the held object to `pos`. Refused, with a conflict counted, with an empty
  // hand or while busy.
  void put(const Vec3& pos, double now);
  // Finishes every step due at or before `now`.
  void update(double now);
  // When the next step is due, if a motion is under way.
  std::optional<double> next_deadline() const;

  // The status flags that hold now: "e_taken" while an object is in the hand, "e_arm_idle"
  // while no motion is under way.
  std::vector<std::string> status() const;
  ArmState state() const { return state_; }
  bool busy() const { return state_ != ArmState::Idle; }
  bool holding() const { return held_.has_value(); }
  std::optional<int> held() const { return held_; }
  int takes_completed() const { return takes_completed_; }
  int failed_takes() const { return failed_takes_; }
  int slips() const { return slips_; }

 private:
  void finish_take();
  void finish_put();
  void slip();

  World& world_;
  ArmState state_ = ArmState::Idle;
  std::optional<int> held_;
  std::optional<int> target_;  // object being grasped
  Vec3 target_pos_ = Vec3::Zero();
  Vec3 put_pos_ = Vec3::Zero();
  double done_at_ = 0;
  std::optional<double> slip_at_;
  bool slipped_once_ = false;
  int takes_completed_ = 0;
  int failed_takes_ = 0;
  int slips_ = 0;
};

}  // namespace arbc::table_clean
