// The referee of the head's input. HeadControl only receives 3-D targets; the referee tells
// where each came from by matching it against what FaceDetector and LookAround published, and
// counts a conflict when a LookAround target reaches the head less than the hold time after a
// face target (the paper's "look around only if not tracking a face"). It is bookkeeping of the
// simulation, not knowledge any module has.
#pragma once

#include <deque>
#include <vector>

#include "examples/table_clean/conflicts.h"
#include "examples/table_clean/geometry.h"

namespace arbc::table_clean {

enum class GazeSource { Face, Search, Unknown };

class GazeReferee {
 public:
  static constexpr double kHold = 1.0;  // seconds, the spec's `hold 1s`

  explicit GazeReferee(ConflictLog& conflicts) : conflicts_(conflicts) {}

  // A module published `value` (a face position, or a LookAround target) at `now`.
  void published(GazeSource source, const Vec3& value, double now);
  // HeadControl received `target` at `now`. Returns where it came from; counts a conflict for
  // a LookAround target within kHold of the last face target.
  GazeSource delivered(const Vec3& target, double now);

  int face_targets() const { return face_targets_; }
  int search_targets() const { return search_targets_; }
  int unknown_targets() const { return unknown_targets_; }
  // Time of the first face target, or negative if none.
  double first_face_target() const { return first_face_target_; }
  double last_face_target() const { return last_face_target_; }
  // For each LookAround target that followed a face target: the time since that face target.
  const std::vector<double>& search_resume_gaps() const { return resume_gaps_; }

 private:
  struct Published {
    GazeSource source;
    Vec3 value;
  };
  static constexpr size_t kRemembered = 64;

  ConflictLog& conflicts_;
  std::deque<Published> recent_;
  int face_targets_ = 0;
  int search_targets_ = 0;
  int unknown_targets_ = 0;
  double first_face_target_ = -1;
  double last_face_target_ = -1;
  bool face_since_search_ = false;
  std::vector<double> resume_gaps_;
};

}  // namespace arbc::table_clean
