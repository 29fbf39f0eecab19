// A Z3 solver's timeout, armed with the time left before a deadline. Z3 reads and writes solver
// parameters under a global lock and reconfigures the solver each time: about a millisecond
// here, more than most of the small queries verify asks (setting it before each query took 70
// of the 180 ms that table_clean's properties over time cost). The reconfiguration also
// changes which model the solver finds next, so when it happens must not depend on timing, or
// a counterexample would differ from run to run (and under the sanitizers' slower code).
//
// So the timeout is set at a solver's first query, and again only once the time left has
// fallen below half of what was set: a query overruns the deadline by at most the time left
// when it started, and a run far from its deadline (every run that ends in time, at the
// default 60 s) sets it once per solver, its answers independent of how fast it runs.
//
// check() below is the one way verify/ asks Z3: with the time left, and an unknown answer
// classified once ("timeout", "resource limit (...)", "solver error: ...").
#pragma once

#include <z3++.h>

#include <chrono>
#include <string>

namespace arbc::verify {

class SolverTimeout {
 public:
  using Clock = std::chrono::steady_clock;

  explicit SolverTimeout(Clock::time_point deadline) : deadline_(deadline) {}

  // Arms `solver`'s timeout as above; false (and nothing set) when no time is left. One
  // SolverTimeout per solver.
  bool arm(z3::solver& solver);

 private:
  Clock::time_point deadline_;
  long long armed_ms_ = 0;  // the timeout last set; 0: none yet
};

// True when Z3's reason for `unknown` is the deadline: its own timeout ("timeout",
// "canceled") or the watchdog's interrupt ("interrupted", verify/solver_watchdog.h).
bool stopped_by_deadline(const std::string& reason_unknown);

// `solver`'s answer (under `assumptions`, when given) within the time `timeout` leaves. Unknown
// when no time is left, when Z3 gives up or when it throws; *reason then says which: "timeout"
// (the deadline, or Z3 stopped by its timeout), "resource limit (WHY)" (Z3's other reasons) or
// "solver error: WHAT". An unknown never passes: the caller reports it as such.
z3::check_result check(z3::solver& solver, SolverTimeout& timeout, std::string* reason,
                       const z3::expr_vector* assumptions = nullptr);

}  // namespace arbc::verify
