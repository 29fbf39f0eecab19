// One test (or a few) per lowering rule of docs/lowering.md, through the real front end.
#include "compiler/lower/lower.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "compiler/lower/lower_test_util.h"
#include "core/effective_guard.h"
#include "tests/support/tree_paths.h"

namespace arbc::lower {

using namespace std::chrono_literals;
namespace {

using testing::compile_ok;
using testing::find_connection;
using V = std::vector<std::string>;

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

const char* kModules = R"(
module Arm    { in cmd: string; out status: list<string>; }
module Rake   { out status: list<string>; }
module Eye    { out objects: list<float>; out face: float; }
module Head   { in gaze: float; }
module Looker { out gaze: float; }
module Mouth  { in text: string; }
module Timer  { out tick: float; }
)";

std::string spec(const std::string& body) { return std::string("app t;\n") + kModules + body; }

// ---- the paper's application ---------------------------------------------------------------

TEST(LowerTest, TableCleanHasThePapersThirteenConnectionsPlusTheSpeakAndDeliveryFeeds) {
  CompiledSpec c = compile_ok(read_file(arbc::testing::source_dir() + "/specs/table_clean.spec"));
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  EXPECT_EQ(app.name, "table_clean");
  ASSERT_EQ(app.connections.size(), 17u);
  int rules = 0, feeds = 0;
  for (const model::Connection& conn : app.connections) {
    if (conn.kind == model::ConnectionKind::Rule) ++rules;
    if (conn.kind == model::ConnectionKind::Feed) {
      ++feeds;
      EXPECT_TRUE(conn.generated);
      EXPECT_EQ(conn.constraint.to_string(), "false");
      EXPECT_TRUE(conn.must_set.empty());
    }
    EXPECT_EQ(conn.monitor, "monitors/" + conn.destination + "__" + conn.name + ".lua");
  }
  EXPECT_EQ(rules, 6);
  // C3, C5, C6, C7, C11, C12, C13, FaceDetector into Speak, and the three delivery events'
  // feeds (PickAndPlace.cmd into PullObject.cmd and into itself, PullObject.cmd into
  // PickAndPlace.cmd)
  EXPECT_EQ(feeds, 11);
  const model::Connection* take = find_connection(app, "PickAndPlace.cmd", "take");
  ASSERT_NE(take, nullptr);
  EXPECT_EQ(
      take->constraint.to_string(),
      "not e_taken and e_arm_idle and e_pull_idle and not e_arm_pulling and not e_arm_picking");
  EXPECT_FALSE(take->generated);
  EXPECT_EQ(take->loc.line, 40);
  // A delivery event (docs/language.md#delivery-events): a feed from what PickAndPlace.cmd
  // delivers into the port that reads it, and its predicate in the model for the resource check.
  const model::Connection* picking =
      find_connection(app, "PullObject.cmd", "feed_PickAndPlace_cmd");
  ASSERT_NE(picking, nullptr);
  EXPECT_EQ(picking->source, "PickAndPlace.cmd");
  EXPECT_EQ(picking->sets, std::vector<std::string>{"e_arm_picking"});
  const model::Event* e = app.find_event("e_arm_picking");
  ASSERT_NE(e, nullptr);
  ASSERT_TRUE(e->predicate);
  EXPECT_EQ(e->source, "PickAndPlace.cmd");
  EXPECT_EQ(app.arbitrated_ports.size(), 4u);
  EXPECT_EQ(app.arbitrated_ports[0].asserts.size(), 3u);
}

// ---- event feeds ----------------------------------------------------------------------------

TEST(LowerTest, FeedsCarryOnlyTheEventsTheirPortReads) {
  CompiledSpec c = compile_ok(read_file(arbc::testing::source_dir() + "/specs/table_clean.spec"));
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  // PickAndPlace.status into PullObject.cmd (C6) carries both flags ...
  const model::Connection* c6 = find_connection(app, "PullObject.cmd", "feed_PickAndPlace_status");
  ASSERT_NE(c6, nullptr);
  EXPECT_EQ(c6->sets, (V{"e_taken", "e_arm_idle"}));
  EXPECT_EQ(c6->unsets, (V{"e_taken", "e_arm_idle"}));
  // ... into HeadControl.gaze (C12) only e_arm_idle: the gaze rules never read e_taken.
  const model::Connection* c12 =
      find_connection(app, "HeadControl.gaze", "feed_PickAndPlace_status");
  ASSERT_NE(c12, nullptr);
  EXPECT_EQ(c12->sets, (V{"e_arm_idle"}));
  EXPECT_EQ(c12->source, "PickAndPlace.status");
  // No feed where nothing is read: PullObject.cmd does not read e_pull_idle.
  EXPECT_EQ(find_connection(app, "PullObject.cmd", "feed_PullObject_status"), nullptr);
}

// `never RULE while EVENT` reads EVENT in RULE's port, so a stream event gets its feed there
// even when no rule of the port reads it; each property keeps its kind and names.
TEST(LowerTest, AnAbsenceReadsItsEventInTheRulesPort) {
  CompiledSpec c = compile_ok(spec(R"(
events from Rake.status { holding = "holding" } lifetime 500ms;
arbitrate Head.gaze by priority {
  track:  from Eye.face hold 1s;
  search: from Looker.gaze;
}
never search while holding;
never search while act_track;
only search after track;
never two track within 1s;
)"));
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  const model::Connection* feed = find_connection(app, "Head.gaze", "feed_Rake_status");
  ASSERT_NE(feed, nullptr);
  EXPECT_EQ(feed->sets, (V{"holding"}));
  using K = model::TemporalProperty::Kind;
  ASSERT_EQ(app.temporal.size(), 4u);
  EXPECT_EQ(app.temporal[0].kind, K::Absence);
  EXPECT_EQ(app.temporal[0].event, "holding");
  EXPECT_EQ(app.temporal[1].event, "act_track");
  EXPECT_EQ(app.temporal[2].kind, K::Precedence);
  EXPECT_EQ(app.temporal[2].rule, "search");
  EXPECT_EQ(app.temporal[2].other, "track");
  EXPECT_EQ(app.temporal[2].port, "Head.gaze");
  EXPECT_EQ(app.temporal[3].kind, K::Spacing);
  EXPECT_EQ(app.temporal[3].window, 1s);
}

TEST(LowerTest, DerivedEventsWithForAreNeverUnsetWithoutForThey) {
  CompiledSpec c = compile_ok(read_file(arbc::testing::source_dir() + "/specs/table_clean.spec"));
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  const model::Connection* unreachable =
      find_connection(app, "Speak.text", "feed_ObjectDetector_objects");
  const model::Connection* face = find_connection(app, "Speak.text", "feed_FaceDetector_face");
  ASSERT_NE(unreachable, nullptr);
  ASSERT_NE(face, nullptr);
  EXPECT_EQ(unreachable->unsets, (V{"e_unreachable"}));
  EXPECT_EQ(face->sets, (V{"e_face_detected"}));
  EXPECT_TRUE(face->unsets.empty());
  EXPECT_EQ(app.find_event("e_face_detected")->lifetime, 1s);
  EXPECT_EQ(app.find_event("e_face_detected")->source, "FaceDetector.face");
}

TEST(LowerTest, StatusFlagsMapToEventNames) {
  CompiledSpec c = compile_ok(spec(R"(
events from Arm.status { e_held = "holding", e_idle } lifetime 500ms;
arbitrate Head.gaze { a: from Looker.gaze when e_held and e_idle; }
)"));
  ASSERT_TRUE(c.ok);
  const MonitorPlan& feed = c.lowered->monitors.back();
  ASSERT_EQ(feed.kind, MonitorPlan::Kind::Feed);
  ASSERT_EQ(feed.status_flags.size(), 2u);
  EXPECT_EQ(feed.status_flags[0].event, "e_held");
  EXPECT_EQ(feed.status_flags[0].flag, "holding");
  EXPECT_EQ(feed.status_flags[1].flag, "e_idle");
  EXPECT_EQ(feed.status_flags[0].lifetime, 500ms);
  EXPECT_EQ(feed.message_name, "status");
}

// ---- by priority ----------------------------------------------------------------------------

TEST(LowerTest, ByPriorityAddsActivityEventsHighestFirst) {
  CompiledSpec c = compile_ok(spec(R"(
event a, b, d;
arbitrate Head.gaze by priority {
  first:  from Looker.gaze when a hold 2s;
  second: from Eye.face when b hold 300ms;
  third:  from Timer.tick when d;
}
)"));
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  // A rule's own activity event is set as it delivers, after the decision: its constraint
  // does not read it, and it is not a must-set (docs/design.md#priorities-and-holds).
  const model::Connection* first = find_connection(app, "Head.gaze", "first");
  EXPECT_EQ(first->constraint.to_string(), "a");
  EXPECT_EQ(find_connection(app, "Head.gaze", "second")->constraint.to_string(),
            "b and not act_first");
  EXPECT_EQ(find_connection(app, "Head.gaze", "third")->constraint.to_string(),
            "d and not act_first and not act_second");
  EXPECT_EQ(first->activity_event, "act_first");
  EXPECT_EQ(first->sets, (V{"act_first"}));
  EXPECT_TRUE(first->must_set.empty());
  EXPECT_EQ(find_connection(app, "Head.gaze", "third")->activity_event, "");
  EXPECT_EQ(model::effective_guard(app, "Head.gaze", *first).to_string(), "a and act_first");
  ASSERT_NE(app.find_event("act_second"), nullptr);
  EXPECT_EQ(app.find_event("act_second")->lifetime, 300ms);
  EXPECT_EQ(app.find_event("act_third"), nullptr);  // the lowest rule has none
}

// `otherwise` as the lowest rule under `by priority`: none of the others' effective guards
// (each with its activity event), and not while a higher rule holds the port.
TEST(LowerTest, OtherwiseUnderPriorityCountsTheActivityEvents) {
  CompiledSpec c = compile_ok(spec(R"(
event a;
arbitrate Head.gaze by priority {
  first:  from Looker.gaze when a hold 1s;
  rest:   from Eye.face when otherwise;
}
)"));
  ASSERT_TRUE(c.ok);
  EXPECT_EQ(find_connection(c.lowered->app, "Head.gaze", "rest")->constraint.to_string(),
            "not (a and act_first) and not act_first");
}

TEST(LowerTest, ActivityEventNameTakenIsAnError) {
  CompiledSpec c = compile_spec_text(spec(R"(
event a, act_first;
arbitrate Head.gaze by priority {
  first:  from Looker.gaze when a hold 2s;
  second: from Eye.face when not a;
}
)"),
                                     "test.spec");
  EXPECT_FALSE(c.ok);
  bool found = false;
  for (const Diagnostic& d : c.diagnostics)
    if (d.message.find("activity event 'act_first'") != std::string::npos) found = true;
  EXPECT_TRUE(found) << frontend::render_diagnostics(c.diagnostics, &c.sources);
}

// ---- otherwise ------------------------------------------------------------------------------

TEST(LowerTest, OtherwiseIsNoneOfTheOtherEffectiveGuards) {
  CompiledSpec c = compile_ok(spec(R"(
event e_face lifetime 1s;
event busy;
arbitrate Head.gaze {
  track:  from Eye.face { set e_face; }
  idle:   from Timer.tick when busy;
  search: from Looker.gaze when otherwise;
}
)"));
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  // track holds exactly when its own event is present (its monitor sets it before step 2).
  EXPECT_EQ(find_connection(app, "Head.gaze", "track")->must_set, (V{"e_face"}));
  EXPECT_EQ(find_connection(app, "Head.gaze", "search")->constraint.to_string(),
            "not (e_face or busy)");
}

// `otherwise` is built before the feeds exist; the guards it negates must be the ones the
// verifier and the docs compute from the finished app (core/effective_guard.h), feeds included.
TEST(LowerTest, OtherwiseNegatesTheCoreEffectiveGuardsOfTheFinishedApp) {
  CompiledSpec c = compile_ok(spec(R"(
event seen, lost, busy;
events from Rake.status { holding = "holding" } lifetime 500ms;
event near = Eye.face : face > 0.5;
arbitrate Head.gaze {
  track:  from Eye.face { set seen; unset lost; accept face > 0.2; }
  voice:  from Timer.tick when holding and near { set busy; set lost; }
  idle:   from Eye.objects when not busy { unset busy; emit 1.0; }
  search: from Looker.gaze when otherwise;
}
)"));
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  ASSERT_GT(app.connections_into("Head.gaze").size(), 4u);  // the feeds are there now
  std::vector<Constraint> guards;
  for (const char* rule : {"track", "voice", "idle"})
    guards.push_back(
        model::effective_guard(app, "Head.gaze", *find_connection(app, "Head.gaze", rule)));
  Constraint expected = Constraint::negate(Constraint::disjunction(std::move(guards)));
  EXPECT_EQ(find_connection(app, "Head.gaze", "search")->constraint.to_string(),
            expected.to_string());
  // track's `not lost` is gone: voice sets lost too (and idle's unset busy: voice sets busy).
  EXPECT_EQ(expected.to_string(), "not (seen or holding and near and busy and lost or not busy)");
}

// ---- body effects ---------------------------------------------------------------------------

TEST(LowerTest, MustSetIsWhatEveryAcceptingPathSets) {
  CompiledSpec c = compile_ok(spec(R"(
event a, b, x, y;
arbitrate Head.gaze {
  r: from Looker.gaze when a {
    set x;
    if gaze > 1.0 { set y; unset b; } else { unset b; }
    if gaze > 2.0 { unset x; set x; } else { accept false; unset x; }
  }
}
)"));
  ASSERT_TRUE(c.ok);
  const model::Connection* r = find_connection(c.lowered->app, "Head.gaze", "r");
  EXPECT_EQ(r->sets, (V{"x", "y"}));
  EXPECT_EQ(r->unsets, (V{"b", "x"}));
  EXPECT_EQ(r->must_set, (V{"x"}));  // y only on one branch; the else branch never accepts
  EXPECT_EQ(r->must_unset, (V{"b"}));
}

// An `every` block runs from trig whatever the message path does, so what it sets counts even
// after an `accept false` that ends every message's path.
TEST(LowerTest, AnEveryBlockAfterAcceptFalseStillSets) {
  CompiledSpec c = compile_ok(spec(R"(
event a, tick_seen;
arbitrate Mouth.text {
  ask: from Eye.face when a { accept false; set a; every 250ms { set tick_seen; } emit "hi"; }
}
)"));
  ASSERT_TRUE(c.ok);
  const model::Connection* ask = find_connection(c.lowered->app, "Mouth.text", "ask");
  EXPECT_EQ(ask->sets, (V{"tick_seen"}));  // `set a` never runs: it follows the accept false
  EXPECT_TRUE(ask->must_set.empty());
}

// ---- throttle, every, connect, script -------------------------------------------------------

TEST(LowerTest, ThrottleAndEveryBecomeConnectionFields) {
  CompiledSpec c = compile_ok(spec(R"(
const PERIOD = 5s;
event a, tick_seen;
arbitrate Mouth.text {
  ask: from Eye.face when a { throttle PERIOD; every 250ms { unset tick_seen; } emit "hi"; }
}
)"));
  ASSERT_TRUE(c.ok);
  const model::Connection* ask = find_connection(c.lowered->app, "Mouth.text", "ask");
  EXPECT_EQ(ask->throttle, 5s);
  EXPECT_EQ(ask->trig_interval, 250ms);
  EXPECT_EQ(ask->unsets, (V{"tick_seen"}));
  EXPECT_TRUE(ask->must_unset.empty());  // `every` runs from trig, not on the message path
}

TEST(LowerTest, ConnectIsAMonitoredPlainConnection) {
  CompiledSpec c = compile_ok(spec(R"(
connect Looker.gaze -> Head.gaze { accept gaze > 0.0; }
)"));
  ASSERT_TRUE(c.ok);
  const model::App& app = c.lowered->app;
  ASSERT_EQ(app.connections.size(), 1u);
  EXPECT_EQ(app.connections[0].kind, model::ConnectionKind::Connect);
  EXPECT_EQ(app.connections[0].name, "from_Looker_gaze");
  EXPECT_EQ(app.connections[0].constraint.to_string(), "true");
  EXPECT_EQ(app.connections[0].monitor, "monitors/Head.gaze__from_Looker_gaze.lua");
  EXPECT_TRUE(app.arbitrated_ports.empty());
}

TEST(LowerTest, ScriptRulesAreOpaqueAndInlineTheirFile) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "arbc_lower_script";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "mine.lua") << "PortMonitor.accept = function(m)\n"
                                     "  PortMonitor.setEvent(\"e_mine\", 1.0)\n"
                                     "  return true\nend\n";
  CompiledSpec c = compile_ok(spec(R"(
event e_mine, a;
arbitrate Head.gaze { mine: from Looker.gaze when a { script "mine.lua"; } }
)"),
                              dir.string());
  ASSERT_TRUE(c.ok);
  const model::Connection* mine = find_connection(c.lowered->app, "Head.gaze", "mine");
  EXPECT_TRUE(mine->opaque);
  EXPECT_EQ(mine->sets, (V{"e_mine"}));
  EXPECT_TRUE(mine->must_set.empty());
  ASSERT_TRUE(c.lowered->monitors[0].script.has_value());
  EXPECT_NE(c.lowered->monitors[0].script->text.find("e_mine"), std::string::npos);
}

TEST(LowerTest, MissingOrBrokenScriptIsADiagnostic) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "arbc_lower_script";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "broken.lua") << "PortMonitor.accept = function(m\n";
  std::string text = spec(R"(
event a;
arbitrate Head.gaze { mine: from Looker.gaze when a { script "nowhere.lua"; } }
)");
  CompiledSpec missing = compile_spec_text(text, "test.spec", dir.string());
  ASSERT_FALSE(missing.ok);
  EXPECT_EQ(missing.diagnostics.back().id, "script-missing");
  EXPECT_NE(missing.diagnostics.back().message.find("script file 'nowhere.lua' not found"),
            std::string::npos);
  EXPECT_GT(missing.diagnostics.back().loc.line, 0);
  text.replace(text.find("nowhere.lua"), 11, "broken.lua");
  CompiledSpec broken = compile_spec_text(text, "test.spec", dir.string());
  ASSERT_FALSE(broken.ok);
  // Sema rejects it (frontend/lua_syntax.h) before lowering reads the script for its text.
  EXPECT_EQ(broken.lowered, nullptr);
  EXPECT_EQ(broken.diagnostics.back().id, "script");
  EXPECT_NE(broken.diagnostics.back().loc.file.str().find("broken.lua"), std::string::npos);
  EXPECT_EQ(broken.diagnostics.back().loc.line, 2);
  EXPECT_NE(broken.diagnostics.back().message.find("does not compile as Lua 5.4"),
            std::string::npos)
      << broken.diagnostics.back().message;
}

TEST(LowerTest, SemanticErrorsStopBeforeLowering) {
  CompiledSpec c =
      compile_spec_text(spec("arbitrate Head.gaze { r: from Eye.nothing; }\n"), "test.spec");
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.lowered, nullptr);
  ASSERT_FALSE(c.diagnostics.empty());
  EXPECT_EQ(c.diagnostics[0].severity, Severity::Error);
}

TEST(LowerTest, UnreadableSpecIsADiagnosticNotACrash) {
  CompiledSpec c = compile_spec("/nonexistent/x.spec");
  EXPECT_FALSE(c.ok);
  ASSERT_FALSE(c.diagnostics.empty());
  EXPECT_EQ(c.diagnostics[0].id, "io");
}

}  // namespace
}  // namespace arbc::lower
