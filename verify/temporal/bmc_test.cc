// The bounded search's traces (verify/temporal/bmc.h): a violation is reported with steps on
// whole microseconds whenever one exists there, because a tests file writes its times to the
// microsecond and the replay must see the same run; off the grid only when nothing on it
// violates.
#include "verify/temporal/bmc.h"

#include <gtest/gtest.h>

#include <cmath>

#include "verify/test_models.h"

namespace arbc::verify::temporal {
namespace {

using Outcome = TemporalResult::Outcome;

// A "violation" at one message into HeadControl.gaze whose time lies in [low, high).
TemporalResult violated_between(const std::string& low, const std::string& high) {
  model::App app = testing::table_clean_model();
  std::string err;
  std::optional<PortShape> shape = port_shape(app, "HeadControl.gaze", &err);
  EXPECT_TRUE(shape) << err;
  z3::context ctx;
  model::TemporalProperty p{model::TemporalProperty::Kind::Spacing,
                            "HeadControl.gaze",
                            "track",
                            1.0,
                            {},
                            "",
                            "",
                            false,
                            {}};
  ViolationAt at = [&](const Unrolling& u, int n) {
    return u.time(n - 1) >= ctx.real_val(low.c_str()) && u.time(n - 1) < ctx.real_val(high.c_str());
  };
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  return bounded_search(*shape, p, 1, 1, at, ctx, nullptr, deadline);
}

bool on_grid(double t) { return std::abs(t * 1e6 - std::round(t * 1e6)) < 1e-6; }

TEST(BoundedSearch, AViolationIsReportedOnWholeMicrosecondsWhenOneIsThere) {
  // From a third of a second (where the solver's first answer lies) to a millisecond later:
  // both ends off the grid, points on it inside.
  TemporalResult r = violated_between("1/3", "1001/3000");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 1u);
  EXPECT_TRUE(on_grid(r.trace[0].time)) << r.trace[0].time;
  EXPECT_GE(r.trace[0].time, 1.0 / 3);
  EXPECT_LT(r.trace[0].time, 1001.0 / 3000);
}

TEST(BoundedSearch, OffTheGridWhenNothingOnItViolates) {
  // A tenth of a microsecond wide, between two grid points: still violated, off the grid.
  TemporalResult r = violated_between("3333333/10000000", "3333334/10000000");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 1u);
  EXPECT_FALSE(on_grid(r.trace[0].time)) << r.trace[0].time;
}

}  // namespace
}  // namespace arbc::verify::temporal
