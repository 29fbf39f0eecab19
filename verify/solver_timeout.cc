#include "verify/solver_timeout.h"

#include <algorithm>

#include "verify/solver_watchdog.h"

namespace arbc::verify {

bool SolverTimeout::arm(z3::solver& solver) {
  long long left =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now()).count();
  if (left <= 0) return false;
  if (armed_ms_ > 0 && 2 * left >= armed_ms_) return true;
  armed_ms_ = std::min<long long>(left, 1u << 30);
  solver.set("timeout", static_cast<unsigned>(armed_ms_));
  return true;
}

bool stopped_by_deadline(const std::string& why) {
  for (const char* word : {"timeout", "canceled", "interrupted"})
    if (why.find(word) != std::string::npos) return true;
  return false;
}

z3::check_result check(z3::solver& solver, SolverTimeout& timeout, std::string* reason,
                       const z3::expr_vector* assumptions) {
  if (!timeout.arm(solver)) {
    *reason = "timeout";
    return z3::unknown;
  }
  try {
    QueryInFlight in_flight(solver.ctx());  // the watchdog may interrupt this query, and only this
    z3::check_result r = assumptions ? solver.check(*assumptions) : solver.check();
    if (r != z3::unknown) return r;
    std::string why = solver.reason_unknown();
    *reason = stopped_by_deadline(why) ? "timeout" : "resource limit (" + why + ")";
  } catch (const z3::exception& e) {
    *reason = stopped_by_deadline(e.msg()) ? "timeout" : std::string("solver error: ") + e.msg();
  }
  return z3::unknown;
}

}  // namespace arbc::verify
