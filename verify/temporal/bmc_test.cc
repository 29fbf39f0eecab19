// The bounded search's traces (verify/temporal/bmc.h): a violation is reported with its steps
// on the runtime's whole nanoseconds, the instants a replay can have (core/instant.h; the
// unrolling counts in them), and on whole microseconds whenever one is there, which reads
// better; a violation that no whole nanosecond has is none the runtime can produce.
#include "verify/temporal/bmc.h"

#include <gtest/gtest.h>

#include "verify/test_models.h"

namespace arbc::verify::temporal {
namespace {

using namespace std::chrono_literals;
using Outcome = TemporalResult::Outcome;

// A "violation" at the last of up to `bound` messages into HeadControl.gaze whose time lies in
// [low, high), nanoseconds as exact rationals ("1000000000/3": a third of a second).
TemporalResult violated_between(const std::string& low, const std::string& high, int bound = 1) {
  model::App app = testing::table_clean_model();
  std::string err;
  std::optional<PortShape> shape = port_shape(app, "HeadControl.gaze", &err);
  EXPECT_TRUE(shape) << err;
  z3::context ctx;
  model::TemporalProperty p{model::TemporalProperty::Kind::Spacing,
                            "HeadControl.gaze",
                            "track",
                            1s,
                            {},
                            "",
                            "",
                            false,
                            {}};
  ViolationAt at = [&](const Unrolling& u, int n) {
    z3::expr t = z3::to_real(u.time(n - 1));
    return t >= ctx.real_val(low.c_str()) && t < ctx.real_val(high.c_str());
  };
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  return bounded_search(*shape, p, 1, bound, at, ctx, nullptr, deadline);
}

bool on_microseconds(Nanos t) { return t.count() % 1000 == 0; }

TEST(BoundedSearch, AViolationIsReportedOnWholeMicrosecondsWhenOneIsThere) {
  // From a third of a second (where the solver's first answer lies) to a millisecond later:
  // both ends off the grid, points on it inside.
  TemporalResult r = violated_between("1000000000/3", "1001000000/3");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 1u);
  EXPECT_TRUE(on_microseconds(r.trace[0].time)) << r.trace[0].time.count();
  EXPECT_GE(r.trace[0].time, Nanos(333'333'334));
  EXPECT_LT(r.trace[0].time, Nanos(333'666'667));
}

TEST(BoundedSearch, OnWholeNanosecondsWhenNoMicrosecondViolates) {
  // A tenth of a microsecond wide, between two microseconds: violated at a whole nanosecond in
  // it, the runtime's instants (core/instant.h), so the tests file can write it exactly.
  TemporalResult r = violated_between("333333300", "333333400");
  ASSERT_EQ(r.outcome, Outcome::Violated);
  ASSERT_EQ(r.trace.size(), 1u);
  EXPECT_FALSE(on_microseconds(r.trace[0].time)) << r.trace[0].time.count();
  EXPECT_GE(r.trace[0].time, Nanos(333'333'300));
  EXPECT_LT(r.trace[0].time, Nanos(333'333'400));
}

TEST(BoundedSearch, AViolationBetweenTwoNanosecondsIsNoneTheRuntimeHas) {
  // A tenth of a nanosecond wide: real times would violate, no instant of the runtime does.
  // Not "violated" (its replay could never show it).
  for (int bound : {1, 3}) {
    TemporalResult r = violated_between("3333333331/10", "3333333332/10", bound);
    EXPECT_EQ(r.outcome, Outcome::HoldsToBound) << "bound " << bound;
    EXPECT_EQ(r.bound, bound);
    EXPECT_TRUE(r.trace.empty());
  }
}

}  // namespace
}  // namespace arbc::verify::temporal
