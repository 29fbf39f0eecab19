// The command line's own parsing and printing (what stays in cli/ once the engines are
// libraries): the values `arbc run` refuses that CLI11 would take, a misspelt option named with
// the one meant, the list bounds a proof hands to the build, and the build's summaries.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include "cli/build_summary.h"
#include "cli/commands.h"
#include "cli/duration_option.h"
#include "cli/parse_error.h"
#include "cli/run_options.h"
#include "cli/verify_gate.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"

namespace arbc::cli {
namespace {

TEST(RunOptions, ADurationNeedsItsUnitAndFitsAMonth) {
  double s = 0;
  std::string err;
  ASSERT_TRUE(parse_run_duration("2min", &s, &err)) << err;
  EXPECT_EQ(s, 120.0);
  ASSERT_TRUE(parse_run_duration("500ms", &s, &err)) << err;
  EXPECT_EQ(s, 0.5);
  ASSERT_TRUE(parse_run_duration("720h", &s, &err)) << err;
  EXPECT_EQ(s, kMaxRunSeconds);
  EXPECT_FALSE(parse_run_duration("60", &s, &err));  // a number without its unit
  EXPECT_EQ(err.rfind("--duration ", 0), 0u) << err;
  EXPECT_FALSE(parse_run_duration("0s", &s, &err));
  EXPECT_FALSE(parse_run_duration("721h", &s, &err));
  EXPECT_NE(err.find("at most 720h (30 days)"), std::string::npos) << err;
  EXPECT_FALSE(parse_run_duration("1e12h", &s, &err));  // issue 40: ran until killed
}

TEST(RunOptions, ASeedIsAWholeNumberThatDoesNotWrap) {
  uint64_t seed = 7;
  std::string err;
  ASSERT_TRUE(parse_seed("18446744073709551615", &seed, &err)) << err;
  EXPECT_EQ(seed, UINT64_MAX);
  ASSERT_TRUE(parse_seed("0", &seed, &err));
  EXPECT_EQ(seed, 0u);
  for (const char* bad : {"-1", "1.5", "18446744073709551616", "", " 1", "0x10", "1e3"}) {
    EXPECT_FALSE(parse_seed(bad, &seed, &err)) << bad;
    EXPECT_NE(err.find("is not a whole number from 0 to 18446744073709551615"), std::string::npos)
        << err;
  }
}

// An option stored in seconds takes a duration's text and hands CLI11 the number.
TEST(DurationOption, TextBecomesSecondsOrTheParsersReason) {
  CLI::App app("test", "arbc-test");
  double every = 0, zero = 1;
  app.add_option("--every", every)->transform(seconds_option(false));
  app.add_option("--zero", zero)->transform(seconds_option(true));
  app.parse(std::vector<std::string>{"250ms", "--every", "0s", "--zero"});  // reversed by CLI11
  EXPECT_EQ(every, 0.25);
  EXPECT_EQ(zero, 0.0);
  CLI::App strict("test", "arbc-test");
  strict.add_option("--every", every)->transform(seconds_option(false));
  EXPECT_THROW(strict.parse(std::vector<std::string>{"0s", "--every"}), CLI::ValidationError);
  EXPECT_THROW(strict.parse(std::vector<std::string>{"fast", "--every"}), CLI::ValidationError);
}

int exit_for(std::vector<std::string> reversed_args, std::string* said) {
  CLI::App app("test", "arbc check");
  std::string format, out;
  app.add_option("--format", format);
  app.add_option("--output", out);
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  int code = kExitOk;
  try {
    app.parse(reversed_args);
  } catch (const CLI::ParseError& e) {
    code = exit_for_parse_error(app, e);
  }
  *said = testing::internal::GetCapturedStderr() + testing::internal::GetCapturedStdout();
  return code;
}

TEST(ParseError, AMisspeltOptionIsNamedWithTheOneMeant) {
  std::string said;
  EXPECT_EQ(exit_for({"json", "--frmat"}, &said), kExitBadInput);
  EXPECT_NE(said.find("arbc check: there is no option --frmat: did you mean '--format'?"),
            std::string::npos)
      << said;
  // Two unknown options, or nothing close: CLI11's own message, still exit 2.
  EXPECT_EQ(exit_for({"--zzzzzz", "--frmat"}, &said), kExitBadInput);
  EXPECT_EQ(said.find("did you mean"), std::string::npos) << said;
  EXPECT_EQ(exit_for({"--help"}, &said), kExitOk);
}

model::App compiled(const std::string& text) {
  lower::CompiledSpec c = lower::compile_spec_text(text, "summary.spec", ".");
  EXPECT_TRUE(c.ok) << frontend::render_diagnostics(c.diagnostics, &c.sources);
  return c.ok ? c.lowered->app : model::App();
}

const char* kTwoRules = R"(app pair;
module Src { out xs: list<float>; out ys: list<float>; }
module Dst { in cmd: float; }
arbitrate Dst.cmd {
  a: from Src.xs { accept len(xs) > 0; emit xs[0]; }
  b: from Src.ys { accept len(ys) > 1; emit ys[1]; }
}
assert Dst.cmd: a -> emitted < 10.0;
)";

TEST(VerifyGate, ListBoundsGoToTheBoundedRulesOnly) {
  model::App app = compiled(kTwoRules);
  VerifyGate gate;
  gate.bounded_rules = {{"Dst.cmd", "b"}, {"Other.port", "a"}};
  gate.list_bound = 4;
  apply_list_bounds(gate, app);
  for (const model::Connection& c : app.connections)
    EXPECT_EQ(c.list_bound, c.name == "b" ? 4 : 0) << c.name;
  EXPECT_EQ(verified_summary(1, 0), "verified: 1 arbitrated port proved exclusive");
  EXPECT_EQ(verified_summary(3, 0), "verified: 3 arbitrated ports proved exclusive");
  EXPECT_EQ(verified_summary(3, 1),
            "verified: 3 arbitrated ports proved exclusive; 1 arbitrated port by priority: a "
            "rule's delivery holds every rule below it off for its hold");
  EXPECT_EQ(verified_summary(0, 2),
            "verified: 2 arbitrated ports by priority: a rule's delivery holds every rule below "
            "it off for its hold");
}

TEST(BuildSummary, SaysWhereAndWhatWasWritten) {
  model::App app = compiled(kTwoRules);
  std::string s = build_summary(app, "summary.spec", "out", "verified: 1 arbitrated port");
  EXPECT_EQ(s.rfind("arbc build: summary.spec -> out/pair/\n  verified: 1 arbitrated port\n", 0),
            0u)
      << s;
  EXPECT_NE(s.find("Dst.cmd"), std::string::npos) << s;
}

// The YARP summary counts what the monitors check (the assert over `emitted`, a list bound)
// and names what no YARP monitor can (the port's exclusivity).
TEST(BuildSummary, YarpSaysWhatItsMonitorsCheckAndWhatTheyCannot) {
  model::App app = compiled(kTwoRules);
  std::string s = yarp_build_summary(app, "summary.spec", "out", "verified", {"contexts/pair/a"});
  EXPECT_NE(s.find("runtime checks in the monitors: 1 assert over `emitted`, said"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("not checked at run time on YARP (its monitors cannot read a port's events): "
                   "the exclusivity of 1 port;"),
            std::string::npos)
      << s;
  for (model::Connection& c : app.connections)
    if (c.name == "b") c.list_bound = 4;
  s = yarp_build_summary(app, "summary.spec", "out", "verified", {});
  EXPECT_NE(s.find("runtime checks in the monitors: 1 assert over `emitted`, 1 list bound,"),
            std::string::npos)
      << s;
  // A spacing of one rule and its source's rate are checked in its monitor; a spacing after
  // another rule is not.
  model::TemporalProperty own, after;
  own.rule = after.rule = "a", own.port = after.port = "Dst.cmd";
  own.window = after.window = std::chrono::seconds(1);
  after.other = "b";
  app.temporal = {own, after};
  app.rates.push_back({"Src.xs", std::chrono::milliseconds(100), {}});
  s = yarp_build_summary(app, "summary.spec", "out", "verified", {});
  EXPECT_NE(s.find("runtime checks in the monitors: 1 assert over `emitted`, 1 list bound, 1 "
                   "spacing of one rule, 1 source rate,"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("the exclusivity of 1 port, 1 property over time;"), std::string::npos) << s;
}

}  // namespace
}  // namespace arbc::cli
