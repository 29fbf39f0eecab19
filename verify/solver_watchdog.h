// The deadline of a verify run, kept even where Z3 does not keep its own timeout. Z3's
// `timeout` parameter is read by the SAT and linear cores but not everywhere: a nonlinear
// integer query (tests/drt found one: `p11 * 5` under a resource pair) ran for minutes with
// a 10 s timeout, so `arbc verify --timeout 10` had no answer. The watchdog is a thread that
// sleeps until the deadline and then interrupts the context (Z3_interrupt, which Z3 documents
// as callable from another thread) until the run is over: a query in flight ends `unknown`
// with reason "interrupted", and SolverTimeout::arm lets no new one start.
//
// Z3 4.8.12 (Debian 12) does not look at the interrupt everywhere either: the query above, a
// sqrt over an int converted to real, ignores both. So a query still running `grace` after the
// deadline calls `on_stuck`, once, on the watchdog's thread: the caller's last word, as the
// thread inside Z3 cannot be stopped (the CLI prints the verdict unknown and ends the process).
#pragma once

#include <z3++.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace arbc::verify {

// A solver query in flight, for the watchdog: it interrupts only while one is. An interrupt
// reaches whatever interruptable Z3 call runs at that moment, and outside a query that is a
// simplify or a model evaluation, which then throws "canceled" where no caller expects it (a
// verify --timeout 1e-9 ended in an uncaught exception). Put one around every check() call.
// Counted per context: a query of another context (the claim tests' own, verify/claim_test.h)
// is no query of the watched one, whose next simplify an interrupt would cancel ("internal
// error: canceled", exit 3 and no report, under load in the differential test).
class QueryInFlight {
 public:
  explicit QueryInFlight(z3::context& ctx);
  ~QueryInFlight();
  QueryInFlight(const QueryInFlight&) = delete;
  QueryInFlight& operator=(const QueryInFlight&) = delete;

 private:
  Z3_context ctx_;
};

class SolverWatchdog {
 public:
  using Clock = std::chrono::steady_clock;

  SolverWatchdog(z3::context& ctx, Clock::time_point deadline,
                 std::function<void()> on_stuck = nullptr,
                 Clock::duration grace = std::chrono::seconds(5));
  ~SolverWatchdog();  // stops the thread; the context is not interrupted after this returns
  SolverWatchdog(const SolverWatchdog&) = delete;
  SolverWatchdog& operator=(const SolverWatchdog&) = delete;

  // Watches `other` too, from now on: a run's queries in a second context (the claim tests'
  // own, ReplayData) must end at the same deadline, or the run outlives it (drt seed 38 spec 186
  // asked that context for witnesses of 1e308 floats for 35 s past a 10 s --timeout). `other`
  // must outlive this watchdog.
  void watch_also(z3::context& other);

  // True once the deadline passed and a context was interrupted at least once.
  bool fired() const;

 private:
  void watch();

  std::vector<z3::context*> contexts_;  // under mutex_
  Clock::time_point deadline_;
  std::function<void()> on_stuck_;
  Clock::duration grace_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  bool fired_ = false;
  std::thread thread_;  // last: started once the fields above are set
};

}  // namespace arbc::verify
