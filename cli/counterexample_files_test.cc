// The files `arbc verify --counterexamples DIR` writes (cli/counterexample_files.h): their names,
// that no counterexample overwrites another's file, and the .txt written for one that cannot be
// replayed as a test.
#include "cli/counterexample_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace arbc::cli {
namespace {

using Kind = model::TemporalProperty::Kind;

model::TemporalProperty property(Kind kind, const std::string& rule,
                                 const std::string& other = "") {
  model::TemporalProperty p;
  p.kind = kind;
  p.port = "Arm.cmd";
  p.rule = rule;
  p.other = other;
  return p;
}

TEST(CounterexampleFiles, ATemporalCounterexampleIsNamedByItsRuleAndKind) {
  std::set<std::string> used;
  EXPECT_EQ(temporal_stem("clean", property(Kind::Spacing, "take"), used), "clean.take");
  EXPECT_EQ(temporal_stem("clean", property(Kind::Spacing, "take", "pull"), used),
            "clean.take.after_pull");
  EXPECT_EQ(temporal_stem("clean", property(Kind::Response, "take", "see"), used),
            "clean.take.response");
  EXPECT_EQ(temporal_stem("clean", property(Kind::Stability, ""), used), "clean.Arm_cmd.stability");
  EXPECT_EQ(temporal_stem("clean", property(Kind::Absence, "pull"), used), "clean.pull.absence");
}

TEST(CounterexampleFiles, TwoPropertiesOfOneRuleAndKindGetTwoFiles) {
  // `never two take within 200ms; never two take within 1s;`: one name each, the second numbered.
  std::set<std::string> used;
  EXPECT_EQ(temporal_stem("clean", property(Kind::Spacing, "take"), used), "clean.take");
  EXPECT_EQ(temporal_stem("clean", property(Kind::Spacing, "take"), used), "clean.take2");
  EXPECT_EQ(temporal_stem("clean", property(Kind::Spacing, "take"), used), "clean.take3");
}

verify::Finding finding(const std::string& check, std::vector<std::string> rules) {
  verify::Finding f;
  f.check = check;
  f.rules = std::move(rules);
  return f;
}

TEST(CounterexampleFiles, ADecisionCounterexampleIsNamedByWhereItsRulesAndItsCheck) {
  std::set<std::string> used;
  verify::Finding pair = finding(verify::kCheckExclusive, {"take", "pull"});
  EXPECT_EQ(finding_stem("clean", "Arm.cmd", pair, used), "clean.Arm_cmd.take.pull.exclusive");
  EXPECT_EQ(finding_stem("clean", "Arm.cmd", pair, used), "clean.Arm_cmd.take.pull.exclusive2");
  EXPECT_EQ(finding_stem("clean", "arm", finding(verify::kCheckResource, {"take", "grip"}), used),
            "clean.arm.take.grip.resource");
  EXPECT_EQ(finding_stem("clean", "Arm.cmd", finding(verify::kCheckAssert, {"take"}), used),
            "clean.Arm_cmd.take.assert");
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(CounterexampleFiles, OneThatCannotBeReplayedIsWrittenAsTextSayingWhy) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(::testing::TempDir()) / "arbc-counterexample-files";
  fs::remove_all(dir);
  verify::VerifyReport report;
  report.app = "clean";
  verify::PortResult port;
  port.port = "Arm.cmd";
  verify::Finding f = finding(verify::kCheckExclusive, {"take", "pull"});
  f.message = "take and pull can both be selected";
  f.not_replayable = "the state needs e_far, which no message sets";
  f.notes.push_back({"make the constraints exclusive", {}});
  verify::Finding proved_nothing = finding(verify::kCheckDead, {"pull"});  // no counterexample
  port.findings = {f, f, proved_nothing};
  report.ports.push_back(port);
  ASSERT_TRUE(write_counterexamples({verify::InputReport("clean.spec", report)}, dir.string()));
  EXPECT_EQ(read(dir / "clean.Arm_cmd.take.pull.exclusive.txt"),
            "Not written as a test: the state needs e_far, which no message sets.\n\n"
            "take and pull can both be selected\nnote: make the constraints exclusive\n");
  EXPECT_TRUE(fs::exists(dir / "clean.Arm_cmd.take.pull.exclusive2.txt"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace arbc::cli
