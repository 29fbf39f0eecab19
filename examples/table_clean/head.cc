#include "examples/table_clean/head.h"

#include <algorithm>
#include <cmath>

namespace arbc::table_clean {

Head::Head(const Vec3& position)
    : position_(position), from_(Vec3(1.0, 0.0, -0.35).normalized()), to_(from_) {}

void Head::look_at(const Vec3& target, double now) {
  ++targets_received_;
  const Vec3 direction = target - position_;
  if (direction.norm() < 1e-9) return;  // a target at the head's centre has no direction
  from_ = gaze_direction(now);
  to_ = direction.normalized();
  start_ = now;
  duration_ = angle_between(from_, to_) / kSpeed;
}

Vec3 Head::gaze_direction(double now) const {
  if (duration_ <= 0 || now >= start_ + duration_) return to_;
  if (now <= start_) return from_;
  const double theta = angle_between(from_, to_);
  const double s = (now - start_) / duration_;
  if (theta < 1e-9 || std::sin(theta) < 1e-9) return to_;
  // Spherical interpolation: constant angular speed along the great circle.
  const Vec3 v = (std::sin((1 - s) * theta) * from_ + std::sin(s * theta) * to_) / std::sin(theta);
  return v.normalized();
}

}  // namespace arbc::table_clean
