#include "examples/table_clean/arm.h"

#include <algorithm>
#include <cmath>

#include "examples/table_clean/world.h"

namespace arbc::table_clean {

void Arm::take(const Vec3& pos, double now) {
  update(now);
  if (holding()) return world_.conflicts().record(ConflictKind::TakeWhileHolding, now);
  if (busy()) return world_.conflicts().record(ConflictKind::TakeWhileArmBusy, now);
  if (world_.rake().out()) return world_.conflicts().record(ConflictKind::TakeWhileRakeOut, now);
  target_.reset();
  if (auto id = world_.object_on_table_near(pos)) {
    const Vec3 at = world_.object(*id).pos;
    if (zone_of(distance_from_robot(at)) == Zone::Hand) {
      target_ = id;
      target_pos_ = at;
    }
  }
  state_ = ArmState::Taking;
  done_at_ = now + kTakeDuration;
}

void Arm::put(const Vec3& pos, double now) {
  update(now);
  if (!holding()) return world_.conflicts().record(ConflictKind::PutWithEmptyHand, now);
  if (busy()) return world_.conflicts().record(ConflictKind::PutWhileArmBusy, now);
  state_ = ArmState::Putting;
  put_pos_ = pos;
  done_at_ = now + kPutDuration;
  // The paper's uncertainty: the object may slip from the hand on its way to the bucket.
  if (world_.perturbations().slip_first_put && !slipped_once_) {
    slipped_once_ = true;
    slip_at_ = now + kPutDuration / 2;
  }
}

void Arm::update(double now) {
  while (auto due = next_deadline()) {
    if (*due > now) break;
    if (slip_at_ && *slip_at_ == *due) {
      slip();
      continue;
    }
    if (state_ == ArmState::Taking)
      finish_take();
    else if (state_ == ArmState::Putting)
      finish_put();
  }
}

std::optional<double> Arm::next_deadline() const {
  if (!busy()) return std::nullopt;
  if (slip_at_) return std::min(*slip_at_, done_at_);
  return done_at_;
}

std::vector<std::string> Arm::status() const {
  std::vector<std::string> flags;
  if (holding()) flags.push_back("e_taken");
  if (!busy()) flags.push_back("e_arm_idle");
  return flags;
}

void Arm::finish_take() {
  state_ = ArmState::Idle;
  // The grasp closes on the object only if it is still where the arm went for it.
  if (target_) {
    TableObject& obj = world_.object(*target_);
    if (obj.place == Place::Table && (obj.pos - target_pos_).norm() <= kGraspTolerance) {
      obj.place = Place::Hand;
      held_ = target_;
      ++takes_completed_;
      target_.reset();
      return;
    }
  }
  target_.reset();
  ++failed_takes_;
}

void Arm::finish_put() {
  state_ = ArmState::Idle;
  if (!held_) return;  // it slipped on the way
  TableObject& obj = world_.object(*held_);
  held_.reset();
  if ((put_pos_ - World::bucket_position()).norm() <= kBucketRadius) {
    obj.place = Place::Bucket;
    obj.pos = World::bucket_position();
    world_.object_binned();
  } else {
    obj.place = Place::Table;
    obj.pos = Vec3(put_pos_.x(), put_pos_.y(), 0.0);
  }
}

void Arm::slip() {
  slip_at_.reset();
  if (!held_) return;
  // It lands back on the table, somewhere the robot can reach with the hand or with the rake.
  TableObject& obj = world_.object(*held_);
  const Zone zone =
      std::uniform_int_distribution<int>(0, 1)(world_.rng()) == 0 ? Zone::Hand : Zone::Tool;
  obj.pos = world_.free_spot(zone, uniform(world_.rng(), -0.6, 0.6), obj.id);
  obj.place = Place::Table;
  held_.reset();
  ++slips_;
}

}  // namespace arbc::table_clean
