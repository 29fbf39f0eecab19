// A violation is reported only when the runtime shows it (docs/design.md#properties-over-time):
// the decision on the replay's deliveries. The replay itself runs on the real runtime in the
// CLI's goldens (tests/verify/golden/temporal.txt); here a replayer that answers fixed
// delivery times checks what arbc makes of each answer.
#include "verify/temporal/confirm.h"

#include <gtest/gtest.h>

namespace arbc::verify::temporal {
namespace {

using Outcome = TemporalResult::Outcome;

// Answers deliveries of 'take' at fixed times (nullopt: the run could not be made).
class FixedReplayer : public TestReplayer {
 public:
  explicit FixedReplayer(std::optional<std::vector<double>> times) : times_(std::move(times)) {}
  std::optional<std::vector<ReplayRecord>> replay(const model::TestCase&, const std::string&,
                                                  std::string* err) const override {
    if (!times_) {
      *err = "the app did not start";
      return std::nullopt;
    }
    std::vector<ReplayRecord> out;
    for (double t : *times_)
      out.push_back({ReplayRecord::Kind::Deliver, nanos_from_seconds(t), "take", "", kNever});
    return out;
  }

 private:
  std::optional<std::vector<double>> times_;
};

TemporalResult violated() {
  TemporalResult r;
  r.property = {model::TemporalProperty::Kind::Spacing,
                "PickAndPlace.cmd",
                "take",
                std::chrono::seconds(1),
                {},
                "",
                "",
                false,
                {}};
  r.outcome = Outcome::Violated;
  r.replay_test = model::TestCase{};
  return r;
}

TEST(Confirm, TwoDeliveriesCloserThanTheWindowConfirm) {
  TemporalResult r = violated();
  std::vector<Finding> findings;
  FixedReplayer replayer(std::vector<double>{0, 0.999});
  std::string seen;
  EXPECT_EQ(confirm_violation(&replayer, r, findings, &seen), Confirmation::Shown);
  EXPECT_EQ(r.outcome, Outcome::Violated);
  EXPECT_TRUE(r.replayed);
  EXPECT_TRUE(findings.empty());
}

TEST(Confirm, AReplayWithoutTheViolationIsNotShownNotAVerdict) {
  // verify.cc then searches the runs a replay makes (PortShape::faithful), or says unknown.
  TemporalResult r = violated();
  std::vector<Finding> findings;
  FixedReplayer replayer(std::vector<double>{0, 1.0});  // exactly the window apart: kept
  std::string seen;
  EXPECT_EQ(confirm_violation(&replayer, r, findings, &seen), Confirmation::NotShown);
  EXPECT_FALSE(r.replayed);
  EXPECT_TRUE(findings.empty());
  EXPECT_NE(seen.find("delivered at 0s, 1s"), std::string::npos) << seen;
}

TEST(Confirm, AReplayThatDoesNotRunIsAnInternalError) {
  TemporalResult r = violated();
  std::vector<Finding> findings;
  FixedReplayer replayer(std::nullopt);
  std::string seen;
  EXPECT_EQ(confirm_violation(&replayer, r, findings, &seen), Confirmation::NotReplayed);
  EXPECT_EQ(r.outcome, Outcome::Unknown);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_NE(findings[0].message.find("did not run"), std::string::npos);
}

TEST(Confirm, NoTestOrNoRuntimeIsUnknownSayingWhy) {
  TemporalResult r = violated();
  r.replay_test.reset();
  r.not_replayable = "'take' is opaque for data (a script)";
  std::vector<Finding> findings;
  FixedReplayer replayer(std::vector<double>{0, 0});
  std::string seen;
  confirm_violation(&replayer, r, findings, &seen);
  EXPECT_EQ(r.outcome, Outcome::Unknown);
  EXPECT_NE(r.unknown_reason.find("opaque for data"), std::string::npos);
  TemporalResult s = violated();
  confirm_violation(nullptr, s, findings, &seen);
  EXPECT_EQ(s.outcome, Outcome::Unknown);
  EXPECT_NE(s.unknown_reason.find("not replayed"), std::string::npos);
  EXPECT_TRUE(findings.empty());
}

TEST(Confirm, HoldingPropertiesAreNotReplayed) {
  TemporalResult r = violated();
  r.outcome = Outcome::HoldsToBound;
  std::vector<Finding> findings;
  std::string seen;
  confirm_violation(nullptr, r, findings, &seen);
  EXPECT_EQ(r.outcome, Outcome::HoldsToBound);
}

// e_x is present from 0s, then 'take' delivers at 0s and 0.999s: the spacing is broken, but so
// is the assumption `assume e_x only after put` (nothing delivered 'put'): the replay is a run
// the spec excludes, so it shows nothing (the mutant confirm-ignores-assumptions of
// scripts/mutation_sites.txt).
class AssumptionBreakingReplayer : public TestReplayer {
 public:
  std::optional<std::vector<ReplayRecord>> replay(const model::TestCase&, const std::string&,
                                                  std::string*) const override {
    return std::vector<ReplayRecord>{
        {ReplayRecord::Kind::Set, Nanos(0), "feed", "e_x", kNever},
        {ReplayRecord::Kind::Deliver, Nanos(0), "take", "", kNever},
        {ReplayRecord::Kind::Deliver, nanos_from_seconds(0.999), "take", "", kNever}};
  }
};

TEST(Confirm, AReplayThatBreaksAnAssumptionDoesNotConfirm) {
  TemporalResult r = violated();
  model::Assumption a;
  a.event = "e_x";
  a.port = "PickAndPlace.cmd";
  a.after = "put";
  r.assumptions = {a};
  std::vector<Finding> findings;
  AssumptionBreakingReplayer replayer;
  std::string seen;
  EXPECT_EQ(confirm_violation(&replayer, r, findings, &seen), Confirmation::NotShown);
  EXPECT_FALSE(r.replayed);
  EXPECT_TRUE(findings.empty());
  EXPECT_NE(seen.find("breaks the assumption"), std::string::npos) << seen;
}

}  // namespace
}  // namespace arbc::verify::temporal
