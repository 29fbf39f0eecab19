#include "examples/table_clean/gaze_referee.h"

namespace arbc::table_clean {

void GazeReferee::published(GazeSource source, const Vec3& value, double now) {
  recent_.push_front({source, value});
  if (recent_.size() > kRemembered) recent_.pop_back();
}

GazeSource GazeReferee::delivered(const Vec3& target, double now) {
  // Values cross the monitors as doubles, so an unchanged value matches to rounding.
  GazeSource source = GazeSource::Unknown;
  for (const Published& p : recent_) {
    if ((p.value - target).cwiseAbs().maxCoeff() <= 1e-9) {
      source = p.source;
      break;
    }
  }
  switch (source) {
    case GazeSource::Face:
      ++face_targets_;
      if (first_face_target_ < 0) first_face_target_ = now;
      last_face_target_ = now;
      face_since_search_ = true;
      break;
    case GazeSource::Search:
      ++search_targets_;
      if (face_since_search_) {
        resume_gaps_.push_back(now - last_face_target_);
        face_since_search_ = false;
      }
      // The tolerance absorbs rounding of `t + hold` in the runtime's event expiry.
      if (last_face_target_ >= 0 && now - last_face_target_ < kHold - 1e-9) {
        conflicts_.record(ConflictKind::SearchDuringHold, now);
      }
      break;
    case GazeSource::Unknown:
      ++unknown_targets_;
      break;
  }
  return source;
}

}  // namespace arbc::table_clean
