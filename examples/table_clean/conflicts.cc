#include "examples/table_clean/conflicts.h"

namespace arbc::table_clean {

std::string_view conflict_name(ConflictKind kind) {
  switch (kind) {
    case ConflictKind::TakeWhileHolding:
      return "take_while_holding";
    case ConflictKind::TakeWhileArmBusy:
      return "take_while_arm_busy";
    case ConflictKind::TakeWhileRakeOut:
      return "take_while_rake_out";
    case ConflictKind::PutWithEmptyHand:
      return "put_with_empty_hand";
    case ConflictKind::PutWhileArmBusy:
      return "put_while_arm_busy";
    case ConflictKind::PullWhileArmBusy:
      return "pull_while_arm_busy";
    case ConflictKind::PullWhileHolding:
      return "pull_while_holding";
    case ConflictKind::SearchDuringHold:
      return "search_during_face_hold";
  }
  return "?";
}

void ConflictLog::record(ConflictKind kind, double now) {
  if (total() == 0) first_time_ = now;
  ++counts_[static_cast<int>(kind)];
}

int ConflictLog::total() const {
  int sum = 0;
  for (int c : counts_) sum += c;
  return sum;
}

std::map<std::string, int> ConflictLog::by_name() const {
  std::map<std::string, int> out;
  for (int k = 0; k < kConflictKinds; ++k) {
    if (counts_[k] > 0) out[std::string(conflict_name(static_cast<ConflictKind>(k)))] = counts_[k];
  }
  return out;
}

}  // namespace arbc::table_clean
