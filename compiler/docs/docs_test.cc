#include <gtest/gtest.h>

#include <sstream>

#include "compiler/docs/decision_table.h"
#include "compiler/docs/graph_docs.h"
#include "compiler/docs/markdown_docs.h"
#include "compiler/docs/monitor_summary.h"

namespace arbc::docs {

using namespace std::chrono_literals;
namespace {

using model::Connection;
using model::ConnectionKind;

// The paper's search-and-track app, lowered by hand: track sets e_face_detected itself.
model::App search_and_track() {
  model::App app;
  app.name = "search_and_track";
  app.description = "Look around until a face appears | then track it.";
  app.modules = {
      {"FaceDetector",
       "faces",
       {{"face", model::Direction::Out, parse_type("{pos: vec3, certainty: float}"), {}}},
       {}},
      {"LookAround", "", {{"gaze", model::Direction::Out, parse_type("vec3"), {}}}, {}},
      {"HeadControl", "", {{"gaze", model::Direction::In, parse_type("vec3"), {}}}, {}}};
  app.events.push_back({"e_face_detected", 1s, "", {}});
  Connection track;
  track.name = "track";
  track.source = "FaceDetector.face";
  track.destination = "HeadControl.gaze";
  track.sets = track.must_set = {"e_face_detected"};
  track.monitor = "monitors/HeadControl.gaze__track.lua";
  Connection search;
  search.name = "search";
  search.source = "LookAround.gaze";
  search.destination = "HeadControl.gaze";
  search.constraint = parse_constraint("not e_face_detected").constraint;
  search.monitor = "monitors/HeadControl.gaze__search.lua";
  Connection feed;
  feed.name = "feed_x";
  feed.kind = ConnectionKind::Feed;
  feed.generated = true;
  feed.source = "FaceDetector.face";
  feed.destination = "HeadControl.gaze";
  feed.constraint = Constraint::constant(false);
  feed.sets = {"x"};
  feed.monitor = "monitors/feed.lua";
  app.connections = {track, search, feed};
  model::ArbitratedPort port;
  port.port = "HeadControl.gaze";
  port.rules = {"track", "search"};
  app.arbitrated_ports = {port};
  return app;
}

TEST(DecisionTableTest, EveryStateSelectsByEffectiveGuard) {
  model::App app = search_and_track();
  DecisionTable t = decision_table(app, app.arbitrated_ports[0]);
  ASSERT_EQ(t.events, std::vector<std::string>{"e_face_detected"});
  ASSERT_TRUE(t.tabulated);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0].selected, std::vector<std::string>{"search"});
  EXPECT_EQ(t.rows[1].selected, std::vector<std::string>{"track"});
}

TEST(DecisionTableTest, OverlapsShowBothRules) {
  model::App app = search_and_track();
  app.connections[0].must_set.clear();  // track's guard is now plain `true`
  DecisionTable t = decision_table(app, app.arbitrated_ports[0]);
  EXPECT_EQ(t.rows[0].selected, (std::vector<std::string>{"track", "search"}));
}

TEST(DecisionTableTest, ManyEventsFallBackToNormalForm) {
  model::App app = search_and_track();
  app.connections[1].constraint =
      parse_constraint("not e_face_detected and (a or b) and (c or d) and e and f and g")
          .constraint;
  DecisionTable t = decision_table(app, app.arbitrated_ports[0]);
  EXPECT_FALSE(t.tabulated);
  EXPECT_TRUE(t.rows.empty());
  EXPECT_EQ(t.rules[1].dnf,
            "a and c and e and not e_face_detected and f and g or "
            "b and c and e and not e_face_detected and f and g or "
            "a and d and e and not e_face_detected and f and g or "
            "b and d and e and not e_face_detected and f and g");
}

TEST(DnfTest, DropsContradictionsAndCapsGrowth) {
  EXPECT_EQ(dnf_text(parse_constraint("a and not a").constraint), "false");
  EXPECT_EQ(dnf_text(parse_constraint("not (a and b)").constraint), "not a or not b");
  std::string big = "(a0 or b0)";
  for (int i = 1; i < 20; ++i)
    big += " and (a" + std::to_string(i) + " or b" + std::to_string(i) + ")";
  std::string text = dnf_text(parse_constraint(big).constraint, 8);
  EXPECT_EQ(text.substr(text.size() - 7), " or ...");
}

// Every row of every table has as many cells as the table's header.
void expect_consistent_tables(const std::string& markdown) {
  std::istringstream in(markdown);
  std::string line;
  int columns = -1;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] != '|') {
      columns = -1;
      continue;
    }
    int pipes = 0;
    for (size_t i = 0; i < line.size(); ++i)
      if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++pipes;
    if (columns < 0) columns = pipes;
    EXPECT_EQ(pipes, columns) << "line " << line_no << ": " << line;
  }
}

// What the connections table says a monitor does comes from the rule's body: an `accept`
// anywhere (here inside an `if`) filters, an `emit` transforms, an empty body passes through.
TEST(MonitorSummaryTest, SaysWhatTheBodyDoes) {
  model::Connection c;
  c.monitor = "monitors/c.lua";
  c.body = model::Body{};
  EXPECT_EQ(docs::monitor_summary(c), "passes every message through unchanged");
  model::BodyStmt accept;
  accept.kind = model::BodyStmt::Kind::Accept;
  model::BodyStmt branch;
  branch.kind = model::BodyStmt::Kind::If;
  branch.else_body.push_back(accept);
  c.body->push_back(branch);
  EXPECT_EQ(docs::monitor_summary(c), "filters");
  model::BodyStmt emit;
  emit.kind = model::BodyStmt::Kind::Emit;
  c.body->push_back(emit);
  c.sets = {"e_busy"};
  EXPECT_EQ(docs::monitor_summary(c), "filters, transforms, sets e_busy");
  c.body.reset();
  c.sets.clear();
  EXPECT_EQ(docs::monitor_summary(c), "a monitor");
  c.monitor.clear();
  EXPECT_EQ(docs::monitor_summary(c), "none");
}

TEST(MarkdownDocsTest, TablesHaveConsistentColumns) {
  model::App app = search_and_track();
  DocsInput input{&app, "  HeadControl.gaze: proved\n", "app.svg", ""};
  std::string md = render_index_markdown(input);
  expect_consistent_tables(md);
  EXPECT_NE(md.find("\nLook around until a face appears | then track it.\n"), std::string::npos);
  EXPECT_NE(md.find("| track | FaceDetector.face | HeadControl.gaze | `true` | sets "
                    "e_face_detected | user |"),
            std::string::npos);
  EXPECT_NE(md.find("| feed_x | FaceDetector.face | HeadControl.gaze | `false` | feeds x into the "
                    "container; never delivers | arbc |"),
            std::string::npos);
  EXPECT_NE(md.find("| 0 | search |"), std::string::npos);
  EXPECT_NE(md.find("| 1 | track |"), std::string::npos);
  EXPECT_NE(
      md.find("## Verification\n\nWhat `arbc verify` says of this app: every claim with its "
              "verdict, and what each rests on.\n\n```text\n  HeadControl.gaze: proved\n```\n"),
      std::string::npos);
}

// The lifetime column says what each `set` gives, not only the declaration's default.
TEST(MarkdownDocsTest, AnEventLivesAsLongAsItsSetsSay) {
  model::App app = search_and_track();
  app.events[0].lifetime.reset();  // `event e_face_detected;`
  model::BodyStmt set_for;
  set_for.kind = model::BodyStmt::Kind::Set;
  set_for.name = "e_face_detected";
  set_for.lifetime = 1s;  // `set e_face_detected for 1s;`
  app.connections[0].body = model::Body{set_for};
  auto row = [&] {
    std::string md = render_index_markdown({&app, {}, "app.svg", ""});
    size_t at = md.find("| `e_face_detected` |");
    return at == std::string::npos ? md : md.substr(at, md.find('\n', at) - at);
  };
  EXPECT_EQ(row(),
            "| `e_face_detected` | monitor code | 1s | HeadControl.gaze / track | "
            "HeadControl.gaze / search |");
  // A second `set` without `for`, inside an `if`: until unset, as the declaration says.
  model::BodyStmt branch;
  branch.kind = model::BodyStmt::Kind::If;
  set_for.lifetime.reset();
  branch.then_body = {set_for};
  app.connections[0].body->push_back(branch);
  EXPECT_NE(row().find("| 1s (track); until unset (track) |"), std::string::npos) << row();
  // A script's own code sets it: the docs cannot say for how long.
  app.connections[0].body.reset();
  EXPECT_NE(row().find("| as its script sets it (track) |"), std::string::npos) << row();
}

// A by-priority port as lowering writes it: the higher rule has an activity event (its hold),
// the lower one reads `not act_track`.
model::App priority_app() {
  model::App app = search_and_track();
  app.arbitrated_ports[0].by_priority = true;
  app.connections[0].constraint = parse_constraint("a").constraint;
  app.connections[0].activity_event = "act_track";
  app.connections[0].sets = {"act_track", "e_face_detected"};
  app.connections[1].constraint =
      parse_constraint("not e_face_detected and not act_track").constraint;
  app.events.push_back({"act_track", 500ms, "", {}});
  return app;
}

TEST(GraphDocsTest, GraphvizAcceptsTheDiagram) {
  model::App app = search_and_track();
  std::string dot = render_dot(app);
  EXPECT_NE(dot.find("style=dashed"), std::string::npos);  // the feed
  // The arbitrator box names its port, each rule with its `when`, and each feed's events;
  // edges end at the rule's row.
  EXPECT_NE(dot.find("<B>A HeadControl.gaze</B>"), std::string::npos);
  EXPECT_NE(dot.find("<B>track</B></TD><TD ALIGN=\"LEFT\" BALIGN=\"LEFT\">when true<BR/>sets "
                     "e_face_detected</TD>"),
            std::string::npos);
  EXPECT_NE(dot.find(">when not e_face_detected</TD>"), std::string::npos);
  EXPECT_NE(dot.find("events from FaceDetector.face: x"), std::string::npos);
  EXPECT_NE(dot.find("\"LookAround\" -> HeadControl_gaze:r1:w"), std::string::npos);
  std::string svg, error;
  ASSERT_TRUE(render_svg(dot, &svg, &error)) << error;
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("HeadControl"), std::string::npos);
  std::string bad_svg;
  EXPECT_FALSE(render_svg("digraph {", &bad_svg, &error));
  EXPECT_EQ(error, "Graphviz `dot` failed on the generated diagram");
}

TEST(GraphDocsTest, PriorityShowsTheOrderTheWhenWrittenAndTheHold) {
  std::string dot = render_dot(priority_app());
  EXPECT_NE(dot.find("<B>A HeadControl.gaze</B> by priority, highest first"), std::string::npos);
  // The activity events lowering added are not part of the `when` the user wrote.
  EXPECT_NE(dot.find("<B>1 track</B></TD><TD ALIGN=\"LEFT\" BALIGN=\"LEFT\">when a<BR/>hold 500ms"
                     "<BR/>sets e_face_detected</TD>"),
            std::string::npos);
  EXPECT_NE(dot.find("<B>2 search</B></TD><TD ALIGN=\"LEFT\" BALIGN=\"LEFT\">when not "
                     "e_face_detected</TD>"),
            std::string::npos);
  std::string mmd = render_mermaid(priority_app());
  EXPECT_NE(mmd.find("[[\"A HeadControl.gaze by priority<br/>1 track: when a, hold 500ms, sets "
                     "e_face_detected<br/>2 search: when not e_face_detected\"]]"),
            std::string::npos);
}

TEST(GraphDocsTest, LongConditionsWrapAndTextIsEscaped) {
  model::App app = search_and_track();
  app.connections[1].constraint =
      parse_constraint("not e_face_detected and e_arm_idle and e_pull_idle and e_unreachable")
          .constraint;
  app.modules[0].name = "Face<Detector>";  // not a valid spec name, but the model allows it
  app.connections[0].source = app.connections[2].source = "Face<Detector>.face";
  std::string dot = render_dot(app);
  EXPECT_NE(dot.find("when not e_face_detected and e_arm_idle and<BR/>e_pull_idle and "
                     "e_unreachable"),
            std::string::npos);
  EXPECT_NE(dot.find("events from Face&lt;Detector&gt;.face: x"), std::string::npos);
  std::string svg, error;
  EXPECT_TRUE(render_svg(dot, &svg, &error)) << error;
}

TEST(GraphDocsTest, MermaidDrawsFeedsDashed) {
  std::string mmd = render_mermaid(search_and_track());
  EXPECT_EQ(mmd.rfind("flowchart LR\n", 0), 0u);
  EXPECT_NE(mmd.find("FaceDetector -->|track| HeadControl_gaze"), std::string::npos);
  EXPECT_NE(mmd.find("FaceDetector -.->|\"x\"| HeadControl_gaze"), std::string::npos);
  EXPECT_NE(mmd.find("HeadControl_gaze[[\"A HeadControl.gaze<br/>track: when true, sets "
                     "e_face_detected<br/>search: when not e_face_detected\"]]"),
            std::string::npos);
}

TEST(GraphDocsTest, CountsWhatADiagramWouldDraw) {
  EXPECT_EQ(diagram_elements(search_and_track()), 3u + 1u + 3u);
}

}  // namespace
}  // namespace arbc::docs
