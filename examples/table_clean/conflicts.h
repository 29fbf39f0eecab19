// Conflicts: commands that a correctly coordinated application never sends
// (examples/table_clean/README.md#conflicts-conflictsh). The modules still react as real ones
// would (they refuse the command), and the world counts each case by kind so that a wrong rule
// shows up in the run's summary.
#pragma once

#include <array>
#include <map>
#include <string>
#include <string_view>

namespace arbc::table_clean {

enum class ConflictKind {
  TakeWhileHolding,
  TakeWhileArmBusy,
  TakeWhileRakeOut,
  PutWithEmptyHand,
  PutWhileArmBusy,
  PullWhileArmBusy,
  PullWhileHolding,
  SearchDuringHold,  // a LookAround target reached HeadControl within the hold after a face
};

inline constexpr int kConflictKinds = 8;

// Stable snake_case name used in summaries and tests, e.g. "take_while_holding".
std::string_view conflict_name(ConflictKind kind);

class ConflictLog {
 public:
  // Records one conflict of `kind` at simulated time `now` (seconds).
  void record(ConflictKind kind, double now);

  int count(ConflictKind kind) const { return counts_[static_cast<int>(kind)]; }
  int total() const;
  // Time of the first conflict, or a negative number when there was none.
  double first_time() const { return first_time_; }
  // Non-zero counts by name, in a stable (alphabetical) order.
  std::map<std::string, int> by_name() const;

 private:
  std::array<int, kConflictKinds> counts_{};
  double first_time_ = -1;
};

}  // namespace arbc::table_clean
