// A Z3 solver's timeout, armed with the time left before a deadline. Z3 reads and writes solver
// parameters under a global lock and reconfigures the solver each time: about a millisecond
// here, more than most of the small queries verify asks (setting it before each query took 70
// of the 180 ms that table_clean's properties over time cost). So the timeout is set again only
// kRearm after the last time, and a query overruns the deadline by at most that.
#pragma once

#include <z3++.h>

#include <chrono>

namespace arbc::verify {

class SolverTimeout {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kRearm{50};

  explicit SolverTimeout(Clock::time_point deadline) : deadline_(deadline) {}

  // Sets `solver`'s timeout to the time left, unless it did so less than kRearm ago; false
  // (and nothing set) when no time is left. One SolverTimeout per solver.
  bool arm(z3::solver& solver);

 private:
  Clock::time_point deadline_;
  bool armed_ = false;
  Clock::time_point armed_at_;
};

}  // namespace arbc::verify
