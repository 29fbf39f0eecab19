#include "verify/solver_timeout.h"

#include <algorithm>

namespace arbc::verify {

bool SolverTimeout::arm(z3::solver& solver) {
  Clock::time_point now = Clock::now();
  auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - now);
  if (left.count() <= 0) return false;
  if (armed_ && now - armed_at_ < kRearm) return true;
  solver.set("timeout", static_cast<unsigned>(std::min<long long>(left.count(), 1u << 30)));
  armed_ = true;
  armed_at_ = now;
  return true;
}

}  // namespace arbc::verify
