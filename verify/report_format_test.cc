// The text, JSON and SARIF writers, and the app.json fixtures under tests/verify/ that the
// command-line golden tests (tests/verify/golden.sh) and the benchmarks read.
#include "verify/report_format.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/app_json.h"
#include "core/check_ids.h"
#include "tests/support/tree_paths.h"
#include "verify/test_models.h"
#include "verify/verify.h"

namespace arbc::verify {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string fixture_path(const std::string& name) {
  return arbc::testing::source_dir() + "/tests/verify/" + name;
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

model::App take_mutant() { return testing::table_clean_take_mutant(); }

// Each fixture is the C++ model serialised; ARBC_UPDATE_GOLDEN=1 rewrites them.
TEST(Fixtures, AppJsonFilesMatchTheModels) {
  std::vector<std::pair<std::string, model::App>> fixtures = {
      {"table_clean.app.json", testing::table_clean_model()},
      {"table_clean_take_mutant.app.json", take_mutant()},
      {"search_and_track.app.json", testing::search_and_track_model()},
      {"table_clean_warnings.app.json", testing::table_clean_with_warnings()},
  };
  for (const auto& [name, app] : fixtures) {
    std::string json = model::to_app_json(app);
    if (std::getenv("ARBC_UPDATE_GOLDEN"))
      std::ofstream(fixture_path(name), std::ios::binary) << json;
    EXPECT_EQ(read(fixture_path(name)), json) << name << " is stale: run with ARBC_UPDATE_GOLDEN=1";
    std::string error;
    std::optional<model::App> back = model::from_app_json(json, &error);
    ASSERT_TRUE(back) << error;
    EXPECT_EQ(model::to_app_json(*back), json);
  }
}

std::vector<InputReport> reports(const model::App& app, VerifyOptions options = {}) {
  std::string error;
  std::optional<VerifyReport> r = verify_app(app, options, &error);
  EXPECT_TRUE(r) << error;
  return {{"app.json", r ? std::move(*r) : VerifyReport{}}};
}

TEST(TextFormat, ProvedSaysWhatWasProvedWithoutTimings) {
  std::string text = format_text(reports(testing::table_clean_model()), nullptr, false);
  EXPECT_THAT(text,
              HasSubstr("PickAndPlace.cmd: proved: rules take, put are never selected together"));
  EXPECT_THAT(text,
              HasSubstr("over 3 events (e_arm_idle, e_pull_idle, e_taken); invariants used: none"));
  EXPECT_THAT(text, HasSubstr("HeadControl.gaze (by priority): proved"));
  EXPECT_THAT(text, HasSubstr("3 asserts hold"));
  EXPECT_THAT(text, HasSubstr("proved: 4 ports, 6 rules; 0 errors, 0 warnings\n"));
  EXPECT_THAT(text, Not(HasSubstr(" s]")));
  EXPECT_THAT(format_text(reports(testing::table_clean_model()), nullptr, true), HasSubstr(" s, "));
}

TEST(TextFormat, LongListsAreCutToOneReadableLine) {
  VerifyReport report;
  report.app = "big";
  PortResult port;
  port.port = "M.in";
  for (int i = 0; i < 1000; ++i) port.rules.push_back("r" + std::to_string(i));
  port.events = {"a", "b"};
  report.ports.push_back(port);
  std::string text = format_text({{"big.json", report}}, nullptr, false);
  EXPECT_THAT(text,
              HasSubstr("rules r0, r1, r2, r3, r4, r5, r6, r7, r8, r9, ..., r999 (1000 in all) "
                        "are never selected together"));
  EXPECT_THAT(text, Not(HasSubstr("r10,")));
  EXPECT_THAT(text, HasSubstr("over 2 events (a, b);"));  // short lists stay whole
  EXPECT_THAT(text, HasSubstr("proved: 1 port, 1000 rules"));
}

// A feed (`when false`, a script that sets events: what `arbc import yarp` writes for a YARP
// monitor that only sets events) never delivers, so the proof's claim names only the rules that
// can; the text, JSON and the summary's rule count agree, and the feed is listed apart.
TEST(TextFormat, AFeedIsNotAmongTheRulesNeverSelectedTogether) {
  model::App app = testing::table_clean_model();
  for (model::Connection& c : app.connections) {
    if (c.name != "put") continue;
    c.constraint = Constraint::constant(false);
    c.opaque = true;
  }
  std::vector<InputReport> inputs = reports(app);
  std::string text = format_text(inputs, nullptr, false);
  EXPECT_THAT(text, HasSubstr("PickAndPlace.cmd: proved: one rule (take), nothing can overlap"));
  EXPECT_THAT(text, HasSubstr("\n    event feeds (never deliver): put\n"));
  EXPECT_THAT(text, HasSubstr("proved: 4 ports, 5 rules;"));
  nlohmann::json port = nlohmann::json::parse(format_json(inputs, false))["inputs"][0]["ports"][0];
  ASSERT_EQ(port["port"], "PickAndPlace.cmd");
  EXPECT_EQ(port["rules"], nlohmann::json::array({"take"}));
  EXPECT_EQ(port["feeds"], nlohmann::json::array({"put"}));
  EXPECT_FALSE(nlohmann::json::parse(format_json(reports(testing::table_clean_model()),
                                                 false))["inputs"][0]["ports"][0]
                   .contains("feeds"));
}

TEST(TextFormat, AssertCountAgreesWithItsVerb) {
  VerifyReport report;
  PortResult port;
  port.port = "M.in";
  port.rules = {"a", "b"};
  port.asserts = 1;
  report.ports.push_back(port);
  EXPECT_THAT(format_text({{"one.json", report}}, nullptr, false), HasSubstr("; 1 assert holds\n"));
  report.ports[0].asserts = 2;
  EXPECT_THAT(format_text({{"two.json", report}}, nullptr, false), HasSubstr("; 2 asserts hold\n"));
}

TEST(TextFormat, RefutedQuotesTheRule) {
  SourceCache sources;
  sources.add("tests/verify/table_clean_take_mutant.spec",
              read(fixture_path("table_clean_take_mutant.spec")));
  std::string text = format_text(reports(take_mutant()), &sources, false);
  EXPECT_THAT(text,
              HasSubstr("tests/verify/table_clean_take_mutant.spec:31:3: error: rules 'take' "
                        "and 'put' of PickAndPlace.cmd can both be selected in one state "
                        "[exclusive]\n    take: from ObjectDetector.objects when e_arm_idle"));
  EXPECT_THAT(text, HasSubstr("present: e_arm_idle, e_pull_idle, e_taken; absent: none"));
  EXPECT_THAT(text, HasSubstr("refuted: 4 ports"));
}

TEST(JsonFormat, CarriesVerdictsFindingsAndCounterexamples) {
  nlohmann::json j = nlohmann::json::parse(format_json(reports(take_mutant()), false));
  EXPECT_EQ(j["schema"], "arbc-verify/1");
  EXPECT_EQ(j["verdict"], "refuted");
  const auto& port = j["inputs"][0]["ports"][0];
  EXPECT_EQ(port["port"], "PickAndPlace.cmd");
  EXPECT_EQ(port["verdict"], "refuted");
  const auto& f = port["findings"][0];
  EXPECT_EQ(f["check"], "exclusive");
  EXPECT_EQ(f["rules"], nlohmann::json({"take", "put"}));
  EXPECT_EQ(f["counterexample"]["present"],
            nlohmann::json({"e_arm_idle", "e_pull_idle", "e_taken"}));
  EXPECT_EQ(f["location"]["line"], 31);
  EXPECT_FALSE(port.contains("stats"));
}

TEST(SarifFormat, OneResultPerFindingWithRuleIdAndLocation) {
  nlohmann::json j = nlohmann::json::parse(format_sarif(reports(take_mutant()), "0.1.0"));
  EXPECT_EQ(j["version"], "2.1.0");
  const auto& run = j["runs"][0];
  const auto& results = run["results"];
  ASSERT_EQ(results.size(), 2u);  // the overlap and the refuted assert
  EXPECT_EQ(results[0]["ruleId"], "exclusive");
  EXPECT_EQ(results[0]["level"], "error");
  const auto& loc = results[0]["locations"][0]["physicalLocation"];
  EXPECT_EQ(loc["artifactLocation"]["uri"], "tests/verify/table_clean_take_mutant.spec");
  EXPECT_EQ(loc["region"]["startLine"], 31);
  EXPECT_EQ(results[1]["ruleId"], "assert");
  bool documented = false;
  for (const auto& rule : run["tool"]["driver"]["rules"]) {
    // `help`, not `helpUri`: SARIF wants an absolute URI there (tests/artifacts checks it).
    documented |= rule["id"] == "exclusive" && !rule.contains("helpUri") &&
                  rule["help"]["text"] == "docs/checks.md#exclusive in arbc's documentation";
  }
  EXPECT_TRUE(documented);
}

TEST(SarifFormat, NoFindingsIsAnEmptyResultsList) {
  nlohmann::json j =
      nlohmann::json::parse(format_sarif(reports(testing::table_clean_model()), "0.1.0"));
  ASSERT_TRUE(j["runs"][0]["results"].is_array());
  EXPECT_TRUE(j["runs"][0]["results"].empty());
}

TEST(SarifFormat, UnknownIsAnErrorResult) {
  VerifyOptions options;
  options.timeout_seconds = 0;
  nlohmann::json j =
      nlohmann::json::parse(format_sarif(reports(testing::table_clean_model(), options), "0.1.0"));
  ASSERT_FALSE(j["runs"][0]["results"].empty());
  EXPECT_EQ(j["runs"][0]["results"][0]["ruleId"], "unknown");
  EXPECT_EQ(j["runs"][0]["results"][0]["level"], "error");
}

// A resource finding's rules go into different ports: JSON names each rule's port, SARIF
// places it at each rule with the rule and its port as a logical location, even where no note
// is at the rule (a rule opaque for data), and names it on a note that is.
TEST(SarifFormat, AResourceFindingHasALocationPerRuleWithItsPort) {
  Finding f;
  f.check = kCheckResource;
  f.message = "resource 'arm' is not proved for 'take' and 'pull'";
  f.loc = {"a.spec", 9, 10, 9, 13};
  f.rules = {"take", "pull"};
  f.rule_ports = {"PickAndPlace.cmd", "PullObject.cmd"};
  f.rule_locs = {{"a.spec", 3, 3, 3, 7}, {"a.spec", 5, 3, 5, 7}};
  f.notes.push_back({"'pull' is selected", {"a.spec", 5, 3, 5, 7}});
  VerifyReport report;
  report.app = "a";
  ResourceResult r;
  r.name = "arm";
  r.verdict = Verdict::Refuted;
  r.findings = {f};
  report.resources = {r};
  std::vector<InputReport> inputs;
  inputs.emplace_back("a.spec", report);

  nlohmann::json j = nlohmann::json::parse(format_json(inputs, false));
  const nlohmann::json& finding = j["inputs"][0]["resources"][0]["findings"][0];
  EXPECT_EQ(finding["rule_ports"], nlohmann::json({"PickAndPlace.cmd", "PullObject.cmd"}));

  j = nlohmann::json::parse(format_sarif(inputs, "0.1.0"));
  const nlohmann::json& related = j["runs"][0]["results"][0]["relatedLocations"];
  ASSERT_EQ(related.size(), 2u) << related.dump(2);
  // The note at 'pull' comes first and gets its name; 'take' has a location of its own.
  EXPECT_EQ(related[0]["message"]["text"], "'pull' is selected");
  EXPECT_EQ(related[0]["logicalLocations"][0]["fullyQualifiedName"], "PullObject.cmd.pull");
  EXPECT_EQ(related[1]["id"], 1);
  EXPECT_EQ(related[1]["message"]["text"], "rule 'take' of PickAndPlace.cmd");
  EXPECT_EQ(related[1]["physicalLocation"]["region"]["startLine"], 3);
  EXPECT_EQ(related[1]["logicalLocations"][0]["name"], "take");
  EXPECT_EQ(related[1]["logicalLocations"][0]["fullyQualifiedName"], "PickAndPlace.cmd.take");
}

// Every check id printed in diagnostics and SARIF helpUris has its section in docs/checks.md.
TEST(Docs, EveryCheckIdHasASectionInChecksMd) {
  std::string docs = read(arbc::testing::source_dir() + "/docs/checks.md");
  for (const char* id : {kCheckExclusive, kCheckDead, kCheckUnfed, kCheckUnused, kCheckOwnership,
                         kCheckComplete, kCheckAssert, kCheckUnknown, kCheckInternal}) {
    EXPECT_THAT(docs, HasSubstr(std::string("\n## ") + id + "\n")) << id;
  }
}

// `arbc check --list-ids` lists every id any stage reports: the verifier's too.
TEST(Docs, EveryCheckIdIsRegistered) {
  std::map<std::string, std::string> stage_of;
  for (const frontend::CheckId& id : frontend::all_check_ids())
    stage_of[std::string(id.id)] = std::string(id.stage);
  for (const char* id : {kCheckExclusive, kCheckDead, kCheckUnfed, kCheckUnused, kCheckOwnership,
                         kCheckComplete, kCheckAssert, kCheckUnknown}) {
    EXPECT_EQ(stage_of[id], "verify") << id;
  }
  EXPECT_EQ(stage_of[kCheckInternal], "internal");
}

}  // namespace
}  // namespace arbc::verify
