// Losses in bulk, said when they start (issue 39: 74,501 of 100,000 flooded commands were
// dropped with nothing said until the end-of-run table). A stretch of losses of one reason on
// one connection (or one input mediated elsewhere) starts when kThreshold of them fall within
// kWindow of run time, and ends once kWindow passes without one; the runtime says one line when
// a stretch starts, never one per message. Only losses count (DropReasonInfo::loss): a rule
// that is not selected, or a feed that consumes its messages, is the arbitration at work.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>

#include "core/instant.h"
#include "runtime/drop_reason.h"

namespace arbc {

class BulkDrops {
 public:
  static constexpr uint64_t kThreshold = 100;
  static constexpr Nanos kWindow = std::chrono::seconds(1);

  // Counts `count` losses for `reason` at `now` (which never goes back); true when they start
  // a stretch, which the caller then says.
  bool count(DropReason reason, uint64_t count, Nanos now) {
    Stretch& s = by_reason_[static_cast<size_t>(reason)];
    bool quiet = s.any && now - s.last >= kWindow;
    s.any = true;
    s.last = now;
    if (s.bulk && !quiet) return false;
    if (quiet || now - s.window_start >= kWindow) {
      s.bulk = false;
      s.window_start = now;
      s.in_window = 0;
    }
    s.in_window += count;
    if (s.in_window < kThreshold) return false;
    s.bulk = true;
    return true;
  }

 private:
  struct Stretch {
    bool any = false;   // a loss was counted
    bool bulk = false;  // in a stretch said already
    Nanos last{0};      // the last loss
    Nanos window_start{0};
    uint64_t in_window = 0;  // losses since window_start
  };
  std::array<Stretch, kDropReasonCount> by_reason_{};
};

}  // namespace arbc
