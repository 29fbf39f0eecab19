// The robot's head: HeadControl turns it towards a 3-D target at a bounded angular speed.
// What FaceDetector can see depends on where it points (World::detect_face).
#pragma once

#include "examples/table_clean/geometry.h"

namespace arbc::table_clean {

class Head {
 public:
  static constexpr double kSpeed = 150.0 * 3.14159265358979323846 / 180.0;  // rad/s
  // Half-angle of the camera's field of view for face detection.
  static constexpr double kFieldOfView = 15.0 * 3.14159265358979323846 / 180.0;

  // The head's centre; initial gaze straight ahead at the table.
  explicit Head(const Vec3& position);

  // Starts turning from where the head points at `now` towards `target`.
  void look_at(const Vec3& target, double now);
  // Unit vector along the gaze at `now` (interpolated along the great circle while turning).
  Vec3 gaze_direction(double now) const;
  const Vec3& position() const { return position_; }
  int targets_received() const { return targets_received_; }

 private:
  Vec3 position_;
  Vec3 from_;
  Vec3 to_;
  double start_ = 0;
  double duration_ = 0;
  int targets_received_ = 0;
};

}  // namespace arbc::table_clean
