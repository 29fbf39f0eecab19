// Each check of docs/checks.md on the table_clean model, with a mutation that triggers it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "verify/test_models.h"
#include "verify/verify.h"

namespace arbc::verify {

using namespace std::chrono_literals;
namespace {

using testing::arbitrated;
using testing::connection;
using ::testing::Contains;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::parse;

VerifyReport run(const model::App& app, VerifyOptions options = {}) {
  std::string error;
  std::optional<VerifyReport> r = verify_app(app, options, &error);
  EXPECT_TRUE(r) << error;
  return r ? std::move(*r) : VerifyReport{};
}

std::vector<const Finding*> findings(const VerifyReport& report, const std::string& check) {
  std::vector<const Finding*> out;
  for (const PortResult& p : report.ports) {
    for (const Finding& f : p.findings) {
      if (f.check == check) out.push_back(&f);
    }
  }
  for (const Finding& f : report.app_findings) {
    if (f.check == check) out.push_back(&f);
  }
  return out;
}

const PortResult& port(const VerifyReport& report, const std::string& name) {
  for (const PortResult& p : report.ports) {
    if (p.port == name) return p;
  }
  throw std::runtime_error("no port " + name);
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(Checks, TableCleanIsProvedWithNoFindings) {
  VerifyReport report = run(testing::table_clean_model());
  EXPECT_EQ(report.verdict, Verdict::Proved);
  ASSERT_EQ(report.ports.size(), 4u);
  for (const PortResult& p : report.ports) {
    EXPECT_EQ(p.verdict, Verdict::Proved) << p.port;
    EXPECT_TRUE(p.findings.empty()) << p.port << ": " << p.findings[0].message;
  }
  EXPECT_TRUE(report.app_findings.empty());
  const PortResult& head = port(report, "HeadControl.gaze");
  EXPECT_THAT(head.events, ElementsAre("act_track", "e_arm_idle", "e_pull_idle", "e_unreachable"));
  EXPECT_THAT(head.rules, ElementsAre("track", "search"));
}

TEST(Checks, SearchAndTrackIsProvedThanksToMustSet) {
  model::App app = testing::search_and_track_model();
  EXPECT_EQ(run(app).verdict, Verdict::Proved);
  connection(app, "track").must_set.clear();  // without it, `true` and `not e` overlap
  VerifyReport report = run(app);
  EXPECT_EQ(report.verdict, Verdict::Refuted);
  ASSERT_EQ(findings(report, "exclusive").size(), 1u);
  EXPECT_TRUE(findings(report, "exclusive")[0]->counterexample->present.empty());
}

TEST(Checks, OpaqueRuleIgnoresMustSet) {
  model::App app = testing::search_and_track_model();
  connection(app, "track").opaque = true;
  EXPECT_EQ(run(app).verdict, Verdict::Refuted);
}

TEST(Checks, ExclusiveNamesTakePutAndCounterexampleWithTaken) {
  model::App app = testing::table_clean_model();
  connection(app, "take").constraint = parse("e_arm_idle and e_pull_idle");
  VerifyReport report = run(app);
  EXPECT_EQ(report.verdict, Verdict::Refuted);
  auto overlaps = findings(report, "exclusive");
  ASSERT_EQ(overlaps.size(), 1u);
  const Finding& f = *overlaps[0];
  EXPECT_THAT(f.rules, ElementsAre("take", "put"));
  EXPECT_EQ(f.port, "PickAndPlace.cmd");
  EXPECT_EQ(f.loc.line, 31);
  // Fewest events: put needs e_taken and e_arm_idle, take needs e_arm_idle and e_pull_idle.
  EXPECT_THAT(f.counterexample->present, ElementsAre("e_arm_idle", "e_pull_idle", "e_taken"));
  EXPECT_TRUE(f.counterexample->absent.empty());
  std::string notes;
  for (const Note& n : f.notes) notes += n.message + "\n";
  EXPECT_THAT(notes, HasSubstr("'take' holds: `e_arm_idle and e_pull_idle`"));
  EXPECT_THAT(
      notes,
      HasSubstr("'put' holds: `e_taken and e_arm_idle` with e_arm_idle present, e_taken present"));
  // The same mutation breaks the first assert.
  auto asserts = findings(report, "assert");
  ASSERT_EQ(asserts.size(), 1u);
  EXPECT_EQ(asserts[0]->loc.line, 67);
  EXPECT_TRUE(contains(asserts[0]->counterexample->present, "e_taken"));
  EXPECT_EQ(port(report, "PullObject.cmd").verdict, Verdict::Proved);
}

TEST(Checks, ByPriorityWithoutActivityEventOverlaps) {
  model::App app = testing::table_clean_model();
  connection(app, "search").constraint = parse("e_unreachable and e_arm_idle and e_pull_idle");
  VerifyReport report = run(app);
  auto overlaps = findings(report, "exclusive");
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_THAT(overlaps[0]->rules, ElementsAre("track", "search"));
  EXPECT_THAT(overlaps[0]->counterexample->present,
              ElementsAre("act_track", "e_arm_idle", "e_pull_idle", "e_unreachable"));
}

TEST(Checks, DeadIsAWarningAndAnErrorWhenStrict) {
  model::App app = testing::table_clean_model();
  connection(app, "pull").constraint = parse("e_taken and not e_taken and e_arm_idle");
  VerifyReport report = run(app);
  auto dead = findings(report, "dead");
  ASSERT_EQ(dead.size(), 1u);
  EXPECT_EQ(dead[0]->severity, Severity::Warning);
  EXPECT_THAT(dead[0]->rules, ElementsAre("pull"));
  EXPECT_EQ(report.verdict, Verdict::Proved);
  VerifyOptions strict;
  strict.strict = true;
  VerifyReport strict_report = run(app, strict);
  EXPECT_EQ(findings(strict_report, "dead")[0]->severity, Severity::Error);
  EXPECT_EQ(strict_report.verdict, Verdict::Refuted);
}

// `when false` with a monitor that sets events is a feed (an imported YARP monitor that never
// delivers): a note that says so, left alone by --strict (which still makes the events pull
// read, now unused, errors). Without events it is still dead.
TEST(Checks, AWhenFalseRuleThatFeedsEventsIsANoteEvenWhenStrict) {
  model::App app = testing::table_clean_model();
  connection(app, "pull").constraint = parse("false");
  connection(app, "pull").opaque = true;  // `script "pull.lua";`: it may set events
  VerifyOptions strict;
  strict.strict = true;
  VerifyReport report = run(app, strict);
  auto dead = findings(report, "dead");
  ASSERT_EQ(dead.size(), 1u);
  EXPECT_EQ(dead[0]->severity, Severity::Note);
  EXPECT_THAT(dead[0]->message, HasSubstr("it is an event feed"));
  EXPECT_THAT(dead[0]->notes[0].message, Not(HasSubstr("remove the rule")));
  EXPECT_FALSE(dead[0]->strict);

  connection(app, "pull").opaque = false;
  connection(app, "pull").sets.clear();
  connection(app, "pull").unsets.clear();
  VerifyReport silent = run(app, strict);
  auto still_dead = findings(silent, "dead");
  ASSERT_EQ(still_dead.size(), 1u);
  EXPECT_EQ(still_dead[0]->severity, Severity::Error);
  EXPECT_THAT(still_dead[0]->notes[0].message, HasSubstr("remove the rule"));
}

TEST(Checks, DeadUnderAnInvariant) {
  model::App app = testing::table_clean_model();
  app.invariants.push_back({parse("not (e_taken and e_arm_idle)"), {}});
  VerifyReport report = run(app);
  auto dead = findings(report, "dead");
  ASSERT_EQ(dead.size(), 1u);
  EXPECT_THAT(dead[0]->rules, ElementsAre("put"));
  EXPECT_THAT(port(report, "PickAndPlace.cmd").invariants,
              ElementsAre("not (e_taken and e_arm_idle)"));
  EXPECT_TRUE(port(report, "Speak.text").invariants.empty());  // it reads neither event
}

TEST(Checks, UnfedWhenAFeedIsMissing) {
  model::App app = testing::table_clean_model();
  std::erase_if(app.connections, [](const model::Connection& c) {
    return c.name == "feed_PullObject_status__PickAndPlace_cmd";
  });
  VerifyReport report = run(app);
  auto unfed = findings(report, "unfed");
  ASSERT_EQ(unfed.size(), 1u);
  EXPECT_EQ(unfed[0]->event, "e_pull_idle");
  EXPECT_EQ(unfed[0]->port, "PickAndPlace.cmd");
  EXPECT_THAT(unfed[0]->rules, ElementsAre("take"));
  EXPECT_EQ(report.verdict, Verdict::Refuted);
}

// A misspelt read (`e_arm_idl`) where the port sets a close name: the note names it and points
// at the connection that sets it. An event no close name is set for gets no guess.
TEST(Checks, UnfedSaysWhichCloseEventThePortSets) {
  model::App app = testing::table_clean_model();
  connection(app, "take").constraint = parse("not e_taken and e_arm_idl and e_pull_idle");
  VerifyReport report = run(app);
  auto unfed = findings(report, "unfed");
  ASSERT_EQ(unfed.size(), 1u);
  EXPECT_EQ(unfed[0]->event, "e_arm_idl");
  ASSERT_GE(unfed[0]->notes.size(), 2u);
  EXPECT_EQ(unfed[0]->notes[0].message,
            "did you mean 'e_arm_idle'? the connection from PickAndPlace.status sets it");
  EXPECT_GT(unfed[0]->notes[0].loc.line, 0);

  model::App missing = testing::table_clean_model();
  std::erase_if(missing.connections, [](const model::Connection& c) {
    return c.name == "feed_PullObject_status__PickAndPlace_cmd";
  });
  VerifyReport far = run(missing);
  auto none = findings(far, "unfed");
  ASSERT_EQ(none.size(), 1u);
  for (const Note& n : none[0]->notes) EXPECT_THAT(n.message, Not(HasSubstr("did you mean")));
}

// A `when` that cannot be false overlaps whatever the events: the counterexample says so of it
// instead of naming the state's events as if they were why; the other rule's note is as before.
TEST(Checks, AConstraintTrueWhateverTheEventsIsSaidToHoldInEveryState) {
  model::App app = testing::table_clean_model();
  connection(app, "take").constraint = parse("e_taken or not e_taken");
  VerifyReport report = run(app);
  auto overlap = findings(report, "exclusive");
  ASSERT_EQ(overlap.size(), 1u);
  std::vector<std::string> notes;
  for (const Note& n : overlap[0]->notes) notes.push_back(n.message);
  EXPECT_THAT(notes, Contains("'take' holds in every state: `e_taken or not e_taken` is true "
                              "whatever the events"));
  EXPECT_THAT(notes, Contains(HasSubstr("'put' holds: `e_taken and e_arm_idle` with")));
}

TEST(Checks, UnfedIsNotReportedWhenAScriptRuleMaySetTheEvent) {
  model::App app = testing::table_clean_model();
  std::erase_if(app.connections, [](const model::Connection& c) {
    return c.name == "feed_PullObject_status__PickAndPlace_cmd";
  });
  connection(app, "put").opaque = true;  // `script "put.lua";`: its setEvent calls are unknown
  EXPECT_TRUE(findings(run(app), "unfed").empty());
}

TEST(Checks, UnfedWhenOnlyAnAssertReadsTheEvent) {
  model::App app = testing::table_clean_model();
  arbitrated(app, "PullObject.cmd").asserts.push_back({"pull", parse("e_pull_idle"), {}, {}});
  VerifyReport report = run(app);  // findings() points into the report: keep it alive
  auto unfed = findings(report, "unfed");
  ASSERT_EQ(unfed.size(), 1u);
  EXPECT_EQ(unfed[0]->event, "e_pull_idle");
  EXPECT_EQ(unfed[0]->port, "PullObject.cmd");
}

TEST(Checks, UnusedWhenAFeedCarriesAnEventNobodyReads) {
  model::App app = testing::table_clean_model();
  connection(app, "feed_FaceDetector_face__Speak_text").sets.push_back("e_taken");
  connection(app, "feed_FaceDetector_face__Speak_text").unsets.push_back("e_taken");
  VerifyReport report = run(app);
  auto unused = findings(report, "unused");
  ASSERT_EQ(unused.size(), 1u);
  EXPECT_EQ(unused[0]->event, "e_taken");
  EXPECT_EQ(unused[0]->severity, Severity::Warning);
  EXPECT_EQ(report.verdict, Verdict::Proved);
}

TEST(Checks, UnusedWhenADeclaredStreamEventIsNeverRead) {
  model::App app = testing::table_clean_model();
  app.events.push_back({"e_extra", 500ms, "PickAndPlace.status", {}});
  VerifyReport report = run(app);  // findings() points into the report: keep it alive
  auto unused = findings(report, "unused");
  ASSERT_EQ(unused.size(), 1u);
  EXPECT_EQ(unused[0]->event, "e_extra");
}

TEST(Checks, OwnershipWhenAMonitorUnsetsWhatItNeverSets) {
  model::App app = testing::table_clean_model();
  connection(app, "ask").unsets.push_back("e_face_detected");
  VerifyReport report = run(app);
  auto own = findings(report, "ownership");
  ASSERT_EQ(own.size(), 1u);
  EXPECT_EQ(own[0]->event, "e_face_detected");
  EXPECT_THAT(own[0]->rules, ElementsAre("ask"));
  EXPECT_EQ(report.verdict, Verdict::Refuted);
}

TEST(Checks, CompleteReportsAStateSelectingNoRule) {
  model::App app = testing::table_clean_model();
  arbitrated(app, "PickAndPlace.cmd").complete = true;
  VerifyReport report = run(app);
  auto complete = findings(report, "complete");
  ASSERT_EQ(complete.size(), 1u);
  EXPECT_TRUE(complete[0]->counterexample->present.empty());  // nothing present: no rule
  EXPECT_EQ(report.verdict, Verdict::Refuted);
}

TEST(Checks, CompleteIsProvedWhenTheRulesCoverEveryState) {
  model::App app = testing::search_and_track_model();
  arbitrated(app, "HeadControl.gaze").complete = true;
  // track holds exactly when e_face_detected (it sets it), search otherwise.
  VerifyReport report = run(app);
  EXPECT_EQ(report.verdict, Verdict::Proved);
  EXPECT_TRUE(findings(report, "complete").empty());
}

TEST(Checks, AssertRefutedWithCounterexample) {
  model::App app = testing::table_clean_model();
  connection(app, "take").constraint = parse("not e_taken and e_arm_idle");
  VerifyReport report = run(app);
  auto asserts = findings(report, "assert");
  ASSERT_EQ(asserts.size(), 1u);
  EXPECT_EQ(asserts[0]->loc.line, 68);  // take -> e_pull_idle
  EXPECT_THAT(asserts[0]->counterexample->present, ElementsAre("e_arm_idle"));
  EXPECT_TRUE(findings(report, "exclusive").empty());
}

TEST(Checks, ExclusiveGroupsAndInvariantsRuleOverlapsOut) {
  model::App app;
  app.name = "domain";
  model::Connection a, b, c;
  a.name = "a", a.source = "S.a", a.destination = "M.p", a.constraint = parse("x");
  a.loc.line = 1;
  b = a, b.name = "b", b.source = "S.b", b.constraint = parse("y");
  c = a, c.name = "feed", c.kind = model::ConnectionKind::Feed, c.constraint = parse("false");
  c.sets = {"x", "y"};
  app.connections = {a, b, c};
  app.arbitrated_ports.push_back({"M.p", false, false, {"a", "b"}, {}, {}});
  EXPECT_EQ(run(app).verdict, Verdict::Refuted);
  model::App grouped = app;
  grouped.exclusive_groups.push_back({{"x", "y", "z"}, {}});
  VerifyReport report = run(grouped);
  EXPECT_EQ(report.verdict, Verdict::Proved);
  EXPECT_EQ(report.ports[0].exclusive_groups, 1);
  // An invariant linking y to w, and w excluding x: closed transitively.
  model::App chained = app;
  chained.invariants.push_back({parse("not y or w"), {}});
  chained.invariants.push_back({parse("not (w and x)"), {}});
  report = run(chained);
  EXPECT_EQ(report.verdict, Verdict::Proved);
  EXPECT_THAT(report.ports[0].events, ElementsAre("w", "x", "y"));
}

TEST(Checks, MustUnsetCountsOnlyWhenNoOtherConnectionSetsTheEvent) {
  model::App app;
  app.name = "unset";
  model::Connection a, b;
  a.name = "a", a.source = "S.a", a.destination = "M.p", a.constraint = parse("true");
  a.sets = {"x"}, a.unsets = {"x"}, a.must_unset = {"x"};
  b = a, b.name = "b", b.source = "S.b", b.constraint = parse("x");
  b.sets = {"x"}, b.unsets.clear(), b.must_unset.clear();
  app.connections = {a, b};
  app.arbitrated_ports.push_back({"M.p", false, false, {"a", "b"}, {}, {}});
  // b sets x too, so a's unset may leave b's entry: x can be present at a's decision.
  EXPECT_EQ(run(app).verdict, Verdict::Refuted);
  app.connections[1].sets.clear();
  model::Connection f;
  f.name = "feed", f.source = "S.f", f.destination = "M.p";
  f.kind = model::ConnectionKind::Feed, f.constraint = parse("false"), f.sets = {"x"};
  app.connections.push_back(f);
  EXPECT_EQ(run(app).verdict, Verdict::Refuted);  // the feed sets x as well
  app.connections[2].sets.clear();
  app.connections[0].sets = {"x"};
  VerifyReport report = run(app);  // only a sets x, and a unsets it before its decision
  EXPECT_EQ(port(report, "M.p").verdict, Verdict::Proved);
}

TEST(Checks, OverlapsBeyondTheCapAreCounted) {
  model::App app;
  app.name = "cap";
  for (int i = 0; i < 20; ++i) {
    model::Connection c;
    c.name = "r" + std::to_string(i);
    c.source = "S.o" + std::to_string(i);
    c.destination = "M.p";
    c.constraint = parse("true");
    app.connections.push_back(c);
  }
  model::ArbitratedPort p{"M.p", false, false, {}, {}, {}};
  for (const model::Connection& c : app.connections) p.rules.push_back(c.name);
  app.arbitrated_ports.push_back(p);
  VerifyReport report = run(app);
  EXPECT_EQ(report.ports[0].overlapping_pairs, 190);
  EXPECT_EQ(report.ports[0].reported_pairs, kDefaultMaxPairsPerPort);
  auto overlaps = findings(report, "exclusive");
  ASSERT_EQ(overlaps.size(), 10u);
  EXPECT_THAT(overlaps[0]->rules, ElementsAre("r0", "r1"));
  EXPECT_THAT(overlaps.back()->notes.back().message, HasSubstr("180 more overlapping pairs"));
}

TEST(Checks, NoTimeLeftIsUnknownAndNeverPasses) {
  VerifyOptions options;
  options.timeout_seconds = 0;
  VerifyReport report = run(testing::table_clean_model(), options);
  EXPECT_EQ(report.verdict, Verdict::Unknown);
  auto unknown = findings(report, "unknown");
  ASSERT_FALSE(unknown.empty());
  EXPECT_EQ(unknown[0]->severity, Severity::Error);
  EXPECT_EQ(report.ports[0].unknown_reason, "timeout");
}

// The exclusivity query itself unanswered: a port whose two guards overlap (no cube shortcut)
// with no time left says so, never passes silently.
TEST(Checks, AnUndecidedExclusivityIsReportedForItsPort) {
  model::App app = testing::table_clean_model();
  testing::connection(app, "take").constraint = parse("e_arm_idle");
  testing::connection(app, "put").constraint = parse("e_arm_idle");
  VerifyOptions options;
  options.timeout_seconds = 0;
  VerifyReport report = run(app, options);
  EXPECT_EQ(report.verdict, Verdict::Unknown);
  bool said = false;
  for (const Finding* f : findings(report, "unknown"))
    said |= f->port == "PickAndPlace.cmd" &&
            f->message.find("whether two rules can be selected together") != std::string::npos;
  EXPECT_TRUE(said) << "no unknown finding for the exclusivity of PickAndPlace.cmd";
}

TEST(Checks, MalformedModelIsBadInput) {
  model::App app = testing::table_clean_model();
  arbitrated(app, "PickAndPlace.cmd").rules.push_back("drop");
  std::string error;
  EXPECT_FALSE(verify_app(app, {}, &error));
  EXPECT_THAT(error, HasSubstr("names rule 'drop'"));
  app = testing::table_clean_model();
  arbitrated(app, "PickAndPlace.cmd").asserts.push_back({"pull", parse("e_taken"), {}, {}});
  error.clear();
  EXPECT_FALSE(verify_app(app, {}, &error));
  EXPECT_THAT(error, HasSubstr("names rule 'pull'"));
}

}  // namespace
}  // namespace arbc::verify
