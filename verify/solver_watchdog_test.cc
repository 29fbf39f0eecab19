#include "verify/solver_watchdog.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace arbc::verify {
namespace {

// Cubes: x^3 + y^3 = z^3 has no positive solution (Fermat, n = 3) and Z3's nonlinear integer
// search does not find that out; it runs until stopped. Z3's own `timeout` parameter is not set
// here, so only the watchdog can end the query.
TEST(SolverWatchdogTest, AQueryZ3DoesNotStopIsInterruptedAtTheDeadline) {
  z3::context ctx;
  z3::solver s(ctx);
  z3::expr x = ctx.int_const("x"), y = ctx.int_const("y"), z = ctx.int_const("z");
  s.add(x > 0 && y > 0 && z > 0 && x * x * x + y * y * y == z * z * z);
  SolverWatchdog watchdog(ctx, SolverWatchdog::Clock::now() + std::chrono::milliseconds(200));
  {
    QueryInFlight in_flight(ctx);
    EXPECT_EQ(s.check(), z3::unknown);
  }
  EXPECT_TRUE(watchdog.fired());
  EXPECT_NE(s.reason_unknown().find("interrupted"), std::string::npos) << s.reason_unknown();
}

TEST(SolverWatchdogTest, ARunThatEndsBeforeTheDeadlineIsNotInterrupted) {
  z3::context ctx;
  z3::solver s(ctx);
  {
    SolverWatchdog watchdog(ctx, SolverWatchdog::Clock::now() + std::chrono::hours(1));
    z3::expr x = ctx.int_const("x");
    s.add(x * x == 49 && x < 0);
    EXPECT_EQ(s.check(), z3::sat);
    EXPECT_FALSE(watchdog.fired());
  }                               // the destructor returns at once, long before the hour
  EXPECT_EQ(s.check(), z3::sat);  // and a later query on the context still runs
}

// A query of another context (the claim tests' own, verify/claim_test.h) is no query of the
// watched one: interrupting the watched context then cancelled its next simplify, and `arbc
// verify` ended "internal error: canceled" with no report (drt_campaign under load).
TEST(SolverWatchdogTest, AQueryOfAnotherContextDoesNotInterruptTheWatchedOne) {
  z3::context watched, other;
  z3::solver s(other);
  z3::expr x = other.int_const("x"), y = other.int_const("y"), z = other.int_const("z");
  s.add(x > 0 && y > 0 && z > 0 && x * x * x + y * y * y == z * z * z);
  s.set("timeout", 400u);  // the other context ends by its own timeout
  SolverWatchdog watchdog(watched, SolverWatchdog::Clock::now() + std::chrono::milliseconds(50));
  {
    QueryInFlight in_flight(other);
    EXPECT_EQ(s.check(), z3::unknown);
  }
  EXPECT_FALSE(watchdog.fired());
  z3::expr a = watched.int_const("a");
  EXPECT_NO_THROW(z3::expr(a + 0).simplify());  // not cancelled
}

// A run's second context (the claim tests' witnesses, verify/claim_test.h) ends at the run's
// deadline too: it was not watched, and drt seed 38 spec 186 asked it for witnesses for 35 s
// after a 10 s --timeout.
TEST(SolverWatchdogTest, AContextWatchedAlsoIsInterruptedAtTheDeadline) {
  z3::context watched, other;
  z3::solver s(other);
  z3::expr x = other.int_const("x"), y = other.int_const("y"), z = other.int_const("z");
  s.add(x > 0 && y > 0 && z > 0 && x * x * x + y * y * y == z * z * z);
  s.set("timeout", 5000u);  // unwatched, the query would end only here, not by an interrupt
  SolverWatchdog watchdog(watched, SolverWatchdog::Clock::now() + std::chrono::milliseconds(200));
  watchdog.watch_also(other);
  {
    QueryInFlight in_flight(other);
    EXPECT_EQ(s.check(), z3::unknown);
  }
  EXPECT_TRUE(watchdog.fired());
  EXPECT_NE(s.reason_unknown().find("interrupted"), std::string::npos) << s.reason_unknown();
  z3::expr a = watched.int_const("a");
  EXPECT_NO_THROW(z3::expr(a + 0).simplify());  // the idle context was not interrupted
}

// A query Z3 4.8.12 does not stop even when interrupted (found by tests/drt: the distance
// between points built from an int field): the watchdog's last word, on_stuck, is called once the
// grace is over. In a child process, as the thread inside Z3 cannot be ended; a Z3 that stops by
// itself ends it too.
TEST(SolverWatchdogDeathTest, AQueryThatIgnoresTheInterruptEndsThroughOnStuck) {
  // r = |0.5 - p| for an int p: sat (p = 0), and Z3 4.8.12 searches forever.
  const char* query =
      "(declare-fun p () Int) (declare-fun r () Real)"
      "(assert (and (>= r 0.0) (= (* r r) (* (- 0.5 (to_real p)) (- 0.5 (to_real p))))))";
  EXPECT_EXIT(
      {
        z3::context ctx;
        z3::solver s(ctx);
        s.from_string(query);
        SolverWatchdog watchdog(
            ctx, SolverWatchdog::Clock::now() + std::chrono::milliseconds(100),
            [] { std::_Exit(7); }, std::chrono::milliseconds(300));
        QueryInFlight in_flight(ctx);
        std::_Exit(s.check() == z3::unknown ? 7 : 9);
      },
      ::testing::ExitedWithCode(7), "");
}

}  // namespace
}  // namespace arbc::verify
