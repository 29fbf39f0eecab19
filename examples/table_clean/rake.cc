#include "examples/table_clean/rake.h"

#include <cmath>

#include "examples/table_clean/world.h"

namespace arbc::table_clean {

std::string_view rake_state_name(RakeState state) {
  switch (state) {
    case RakeState::Idle:
      return "idle";
    case RakeState::Fetching:
      return "fetching";
    case RakeState::Reaching:
      return "reaching";
    case RakeState::Pulling:
      return "pulling";
    case RakeState::Returning:
      return "returning";
  }
  return "?";
}

void Rake::pull(const Vec3& pos, double now) {
  update(now);
  if (out()) {
    ++redundant_pulls_;
    return;
  }
  if (world_.arm().busy()) return world_.conflicts().record(ConflictKind::PullWhileArmBusy, now);
  if (world_.arm().holding()) {
    return world_.conflicts().record(ConflictKind::PullWhileHolding, now);
  }
  target_ = world_.object_on_table_near(pos);
  if (target_) target_pos_ = world_.object(*target_).pos;
  phase_end_ = now;
  start_phase(RakeState::Fetching, kFetchDuration);
}

void Rake::cancel(double now) {
  update(now);
  if (state_ == RakeState::Idle || state_ == RakeState::Returning) {
    ++cancels_ignored_;
    return;
  }
  ++cancels_honoured_;
  phase_end_ = now;
  start_phase(RakeState::Returning, kReturnDuration);
}

void Rake::update(double now) {
  while (out() && phase_end_ <= now) advance_phase();
}

std::optional<double> Rake::next_deadline() const {
  if (!out()) return std::nullopt;
  return phase_end_;
}

std::vector<std::string> Rake::status() const {
  if (out()) return {};
  return {"e_pull_idle"};
}

void Rake::start_phase(RakeState state, double duration) {
  state_ = state;
  phase_end_ += duration;
}

void Rake::advance_phase() {
  switch (state_) {
    case RakeState::Idle:
      return;
    case RakeState::Fetching:
      start_phase(RakeState::Reaching, kReachDuration);
      // The paper's uncertainty: a person moves the target into the robot's reach while the
      // rake is on its way to it.
      if (target_ && world_.perturbations().person_moves_first_rake_target && !perturbed_once_) {
        perturbed_once_ = true;
        const int id = *target_;
        world_.schedule(phase_end_ - kReachDuration / 2,
                        [this, id] { world_.person().move_into_hand_reach(id); });
      }
      return;
    case RakeState::Reaching:
      start_phase(RakeState::Pulling, kPullDuration);
      return;
    case RakeState::Pulling: {
      // The rake drags the object, if it is still where the rake went for it, into hand reach.
      if (target_) {
        TableObject& obj = world_.object(*target_);
        if (obj.place == Place::Table && (obj.pos - target_pos_).norm() <= kGraspTolerance) {
          obj.pos = world_.free_spot(Zone::Hand, std::atan2(obj.pos.y(), obj.pos.x()), obj.id);
          ++objects_pulled_;
        }
      }
      target_.reset();
      start_phase(RakeState::Returning, kReturnDuration);
      return;
    }
    case RakeState::Returning:
      state_ = RakeState::Idle;
      target_.reset();
      return;
  }
}

}  // namespace arbc::table_clean
