// The verdict of `arbc run` (cli/run_verdict.h): what fails a run without an environment, and
// how the runtime checks' violations change a verdict with and without --runtime-checks fail.
#include "cli/run_verdict.h"

#include <gtest/gtest.h>

namespace arbc::cli {
namespace {

ConnectionStats connection(const std::string& name) {
  ConnectionStats s;
  s.name = name;
  return s;
}

void drop(ConnectionStats& s, DropReason r, uint64_t n) { s.dropped[static_cast<int>(r)] = n; }

TEST(RunVerdict, WithoutAnEnvironmentACleanRunSucceedsAndSaysHowItWasJudged) {
  ConnectionStats nav = connection("nav");
  nav.arrived = nav.delivered = 10;
  RunVerdict v = judge_without_environment({nav}, {});
  EXPECT_TRUE(v.success);
  EXPECT_EQ(v.text,
            "success (no environment; judged by quarantined connections and messages of the "
            "wrong type)");
}

TEST(RunVerdict, TheMediationsOwnDropsDoNotFailARun) {
  ConnectionStats nav = connection("nav");
  for (DropReason r : {DropReason::Rejected, DropReason::NotSelected, DropReason::Throttled,
                       DropReason::QueueFull, DropReason::BadValue, DropReason::LostInTransit})
    drop(nav, r, 3);
  InputStats in;
  in.port = "Base.cmd";
  in.dropped[static_cast<int>(DropReason::QueueFull)] = 2;
  EXPECT_TRUE(judge_without_environment({nav}, {in}).success);
}

TEST(RunVerdict, AQuarantineOrMessagesOfTheWrongTypeFailARunAndAreNamed) {
  ConnectionStats nav = connection("nav"), joy = connection("joy");
  nav.quarantined = true;
  drop(joy, DropReason::BadType, 4);
  InputStats in;
  in.port = "Base.cmd";
  in.dropped[static_cast<int>(DropReason::BadType)] = 1;
  RunVerdict v = judge_without_environment({nav, joy}, {in});
  EXPECT_FALSE(v.success);
  EXPECT_EQ(v.text,
            "failure (no environment; judged by quarantined connections and messages of the "
            "wrong type: nav quarantined, 4 bad-type into joy, 1 bad-type into Base.cmd)");
}

TEST(RunVerdict, AnEnvironmentDecides) {
  EXPECT_EQ(judge_by_environment(true).text, "success");
  EXPECT_FALSE(judge_by_environment(false).success);
  EXPECT_EQ(judge_by_environment(false).text, "failure");
}

std::vector<ClaimViolation> two_broken() {
  ClaimViolation spacing{std::chrono::milliseconds(1500), "never two take within 1s",
                         "delivered 0.5s apart", false};
  ClaimViolation rate{std::chrono::seconds(2), "given Nav.cmd every 100ms", "no message for 300ms",
                      true};
  return {spacing, rate};
}

TEST(RunVerdict, BrokenClaimsFailTheRunOnlyWithRuntimeChecksFail) {
  RunVerdict ok = judge_by_environment(true);
  RunVerdict kept = with_broken_claims(ok, two_broken(), /*fail=*/false);
  EXPECT_TRUE(kept.success);
  EXPECT_EQ(kept.text, "success");
  RunVerdict failed = with_broken_claims(ok, two_broken(), /*fail=*/true);
  EXPECT_FALSE(failed.success);
  EXPECT_EQ(failed.text,
            "failure (runtime checks: never two take within 1s at 1.5s; assumption given "
            "Nav.cmd every 100ms at 2s broken)");
  EXPECT_TRUE(with_broken_claims(ok, {}, /*fail=*/true).success);
}

TEST(RunVerdict, AFailureForAnotherReasonIsKeptBesideTheBrokenClaims) {
  RunVerdict env = judge_by_environment(false);
  RunVerdict v = with_broken_claims(env, {two_broken()[0]}, /*fail=*/true);
  EXPECT_FALSE(v.success);
  EXPECT_EQ(v.text, "failure (runtime checks: never two take within 1s at 1.5s broken; failure)");
  // A success without an environment says how it was judged; that is not a failure to keep.
  RunVerdict clean = judge_without_environment({connection("nav")}, {});
  EXPECT_EQ(with_broken_claims(clean, {two_broken()[0]}, true).text,
            "failure (runtime checks: never two take within 1s at 1.5s broken)");
}

}  // namespace
}  // namespace arbc::cli
