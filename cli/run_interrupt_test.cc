// The interrupt's watchdog (cli/run_interrupt.h): a run that returns within its grace is left
// alone; one that does not is given up on (exit 3) after the grace, or after the grace and the
// patience a slow but bounded phase (closing the DDS transport) asks for.
#include "cli/run_interrupt.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>

namespace arbc::cli {
namespace {

void sleep_seconds(double s) { usleep(static_cast<useconds_t>(s * 1e6)); }

TEST(RunInterrupt, ARunThatReturnsWithinTheGraceIsLeftAlone) {
  RunInterrupt interrupt;
  interrupt.watch(
      0.5, [] { return 0.0; }, [](double) { std::fprintf(stderr, "gave up\n"); });
  std::raise(SIGTERM);
  EXPECT_TRUE(interrupt.flag()->load());
  EXPECT_STREQ(interrupt.signal_name(), "SIGTERM");
  EXPECT_TRUE(interrupt.run_returned());
}

TEST(RunInterrupt, PatienceExtendsTheGrace) {
  // Without the patience the watchdog would end the process 0.05 s after the signal.
  RunInterrupt interrupt;
  interrupt.watch(
      0.05, [] { return 5.0; }, [](double) { std::fprintf(stderr, "gave up\n"); });
  std::raise(SIGTERM);
  sleep_seconds(0.4);
  EXPECT_TRUE(interrupt.run_returned());
}

TEST(RunInterruptDeathTest, AStuckRunIsGivenUpOnAfterTheGraceAndThePatience) {
  auto stuck = [](double patience) {
    RunInterrupt interrupt;
    interrupt.watch(
        0.05, [patience] { return patience; },
        [](double waited) { std::fprintf(stderr, "gave up after %.2f s\n", waited); });
    std::raise(SIGINT);
    sleep_seconds(3);  // the run never returns
  };
  EXPECT_EXIT(stuck(0), testing::ExitedWithCode(3), "gave up after 0.05 s");
  EXPECT_EXIT(stuck(0.2), testing::ExitedWithCode(3), "gave up after 0.25 s");
}

}  // namespace
}  // namespace arbc::cli
