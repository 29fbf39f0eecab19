#include "verify/test_models.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace arbc::verify::testing {
using namespace std::chrono_literals;

namespace {

model::SourceLocation at(int line, int column, int length) {
  return {table_clean_spec_path(), line, column, line, column + length};
}

model::Port port(const std::string& name, model::Direction dir, const std::string& type) {
  model::Port p;
  p.name = name;
  p.direction = dir;
  p.type = parse_type(type);
  return p;
}

model::Module module(const std::string& name, std::vector<model::Port> ports) {
  model::Module m;
  m.name = name;
  m.ports = std::move(ports);
  return m;
}

model::Connection rule(const std::string& name, const std::string& from, const std::string& to,
                       const std::string& when, model::SourceLocation loc) {
  model::Connection c;
  c.name = name;
  c.source = from;
  c.destination = to;
  c.kind = model::ConnectionKind::Rule;
  c.constraint = parse(when);
  c.loc = std::move(loc);
  return c;
}

// A generated feed: copies `events` from a source port into the port's container.
model::Connection feed(const std::string& from, const std::string& to,
                       std::vector<std::string> events, model::SourceLocation loc) {
  model::Connection c;
  std::string src = from, dst = to;
  for (char& ch : src) ch = ch == '.' ? '_' : ch;
  for (char& ch : dst) ch = ch == '.' ? '_' : ch;
  c.name = "feed_" + src + "__" + dst;
  c.source = from;
  c.destination = to;
  c.kind = model::ConnectionKind::Feed;
  c.generated = true;
  c.constraint = Constraint::constant(false);
  c.sets = events;
  c.unsets = events;
  c.loc = std::move(loc);
  return c;
}

model::Event event(const std::string& name, std::chrono::milliseconds lifetime,
                   const std::string& source, model::SourceLocation loc) {
  model::Event e;
  e.name = name;
  if (lifetime > Nanos(0)) e.lifetime = lifetime;
  e.source = source;
  e.loc = std::move(loc);
  return e;
}

model::ArbitratedPort arbitrated_port(const std::string& name, std::vector<std::string> rules,
                                      model::SourceLocation loc) {
  model::ArbitratedPort a;
  a.port = name;
  a.rules = std::move(rules);
  a.loc = std::move(loc);
  return a;
}

// Points every location at a mutated copy of the spec, so diagnostics quote lines as changed.
void relocate(model::App& app, const std::string& spec) {
  app.spec_file = spec;
  for (model::Event& e : app.events) e.loc.file = spec;
  for (model::Connection& c : app.connections) c.loc.file = spec;
  for (model::ArbitratedPort& p : app.arbitrated_ports) {
    p.loc.file = spec;
    for (model::Assertion& a : p.asserts) a.loc.file = spec;
  }
}

}  // namespace

std::string table_clean_spec_path() { return "tests/verify/table_clean.spec"; }

Constraint parse(const std::string& text) {
  ConstraintParse p = parse_constraint(text);
  if (!p.ok) throw std::runtime_error("bad constraint in a test: " + text + ": " + p.error);
  return p.constraint;
}

// table_clean's four arbitrated ports, with PickAndPlace.cmd's asserts.
static void add_table_clean_ports(model::App& app) {
  model::ArbitratedPort pick = arbitrated_port("PickAndPlace.cmd", {"take", "put"}, at(30, 11, 16));
  pick.asserts = {{"take", parse("not e_taken"), at(67, 1, 6), {}},
                  {"take", parse("e_pull_idle"), at(68, 1, 6), {}},
                  {"put", parse("e_taken"), at(69, 1, 6), {}}};
  app.arbitrated_ports.push_back(pick);
  app.arbitrated_ports.push_back(arbitrated_port("PullObject.cmd", {"pull"}, at(42, 11, 14)));
  model::ArbitratedPort head =
      arbitrated_port("HeadControl.gaze", {"track", "search"}, at(52, 11, 16));
  head.by_priority = true;
  app.arbitrated_ports.push_back(head);
  app.arbitrated_ports.push_back(arbitrated_port("Speak.text", {"ask"}, at(60, 11, 10)));
}

model::App table_clean_model() {
  using model::Direction;
  model::App app;
  app.name = "table_clean";
  app.description =
      "Clear the table: pick reachable objects, rake far ones closer, ask a person for the rest.";
  app.spec_file = table_clean_spec_path();
  const std::string object = "{pos: vec3, dist: float}";
  app.modules = {
      module("ObjectDetector", {port("objects", Direction::Out, "list<" + object + ">")}),
      module("BucketDetector", {port("bucket", Direction::Out, "vec3")}),
      module("FaceDetector", {port("face", Direction::Out, "{pos: vec3, certainty: float}")}),
      module("LookAround", {port("gaze", Direction::Out, "vec3")}),
      module("HeadControl", {port("gaze", Direction::In, "vec3")}),
      module("PickAndPlace", {port("cmd", Direction::In, "{verb: string, pos: vec3}"),
                              port("status", Direction::Out, "list<string>")}),
      module("PullObject", {port("cmd", Direction::In, "{verb: string, pos: vec3}"),
                            port("status", Direction::Out, "list<string>")}),
      module("Speak", {port("text", Direction::In, "string")}),
  };
  app.events = {
      event("e_taken", 500ms, "PickAndPlace.status", at(23, 35, 7)),
      event("e_arm_idle", 500ms, "PickAndPlace.status", at(23, 44, 10)),
      event("e_pull_idle", 500ms, "PullObject.status", at(24, 35, 11)),
      event("e_unreachable", 0ms, "ObjectDetector.objects", at(27, 7, 13)),
      event("e_face_detected", 1000ms, "FaceDetector.face", at(28, 7, 15)),
      event("act_track", 1000ms, "", at(53, 3, 5)),
  };

  // PickAndPlace.cmd
  app.connections.push_back(rule("take", "ObjectDetector.objects", "PickAndPlace.cmd",
                                 "not e_taken and e_arm_idle and e_pull_idle", at(31, 3, 4)));
  app.connections.push_back(rule("put", "BucketDetector.bucket", "PickAndPlace.cmd",
                                 "e_taken and e_arm_idle", at(37, 3, 3)));
  app.connections.push_back(
      feed("PickAndPlace.status", "PickAndPlace.cmd", {"e_taken", "e_arm_idle"}, at(23, 1, 6)));
  app.connections.push_back(
      feed("PullObject.status", "PickAndPlace.cmd", {"e_pull_idle"}, at(24, 1, 6)));
  // PullObject.cmd
  app.connections.push_back(rule("pull", "ObjectDetector.objects", "PullObject.cmd",
                                 "not e_taken and e_arm_idle", at(43, 3, 4)));
  app.connections.push_back(
      feed("PickAndPlace.status", "PullObject.cmd", {"e_taken", "e_arm_idle"}, at(23, 1, 6)));
  // HeadControl.gaze by priority: track gets the activity event act_track (set by the runtime
  // each time track delivers, lifetime `hold`), search requires its absence.
  model::Connection track = rule("track", "FaceDetector.face", "HeadControl.gaze",
                                 "e_unreachable and e_arm_idle and e_pull_idle", at(53, 3, 5));
  track.sets = {"act_track"};
  track.activity_event = "act_track";
  app.connections.push_back(track);
  app.connections.push_back(rule("search", "LookAround.gaze", "HeadControl.gaze",
                                 "e_unreachable and e_arm_idle and e_pull_idle and not act_track",
                                 at(57, 3, 6)));
  app.connections.push_back(
      feed("ObjectDetector.objects", "HeadControl.gaze", {"e_unreachable"}, at(27, 1, 5)));
  app.connections.push_back(
      feed("PickAndPlace.status", "HeadControl.gaze", {"e_arm_idle"}, at(23, 1, 6)));
  app.connections.push_back(
      feed("PullObject.status", "HeadControl.gaze", {"e_pull_idle"}, at(24, 1, 6)));
  // Speak.text
  model::Connection ask = rule("ask", "FaceDetector.face", "Speak.text",
                               "e_unreachable and e_face_detected", at(61, 3, 3));
  ask.throttle = 5s;
  app.connections.push_back(ask);
  app.connections.push_back(
      feed("ObjectDetector.objects", "Speak.text", {"e_unreachable"}, at(27, 1, 5)));
  app.connections.push_back(
      feed("FaceDetector.face", "Speak.text", {"e_face_detected"}, at(28, 1, 5)));
  add_table_clean_ports(app);
  return app;
}

model::App table_clean_take_mutant() {
  model::App app = table_clean_model();
  connection(app, "take").constraint = parse("e_arm_idle and e_pull_idle");
  relocate(app, "tests/verify/table_clean_take_mutant.spec");
  return app;
}

model::App table_clean_with_warnings() {
  model::App app = table_clean_model();
  connection(app, "pull").constraint = parse("e_taken and not e_taken and e_arm_idle");
  model::Connection& feed = connection(app, "feed_FaceDetector_face__Speak_text");
  feed.sets.push_back("e_taken");
  feed.unsets.push_back("e_taken");
  relocate(app, "tests/verify/table_clean_warnings.spec");
  return app;
}

model::App search_and_track_model() {
  using model::Direction;
  model::App app;
  app.name = "search_and_track";
  app.spec_file = "search_and_track.spec";
  app.modules = {
      module("FaceDetector", {port("face", Direction::Out, "{pos: vec3, certainty: float}")}),
      module("LookAround", {port("gaze", Direction::Out, "vec3")}),
      module("HeadControl", {port("gaze", Direction::In, "vec3")}),
  };
  app.events = {event("e_face_detected", 1000ms, "", {})};
  // The paper's pair: track's own monitor sets e_face_detected whenever it accepts, so at its
  // decision the event is present and search (`not e_face_detected`) cannot hold.
  model::Connection track = rule("track", "FaceDetector.face", "HeadControl.gaze", "true",
                                 {"search_and_track.spec", 5, 3, 5, 8});
  track.sets = {"e_face_detected"};
  track.must_set = {"e_face_detected"};
  app.connections.push_back(track);
  app.connections.push_back(rule("search", "LookAround.gaze", "HeadControl.gaze",
                                 "not e_face_detected", {"search_and_track.spec", 9, 3, 9, 9}));
  app.arbitrated_ports.push_back(arbitrated_port("HeadControl.gaze", {"track", "search"},
                                                 {"search_and_track.spec", 4, 11, 4, 27}));
  return app;
}

model::Connection& connection(model::App& app, const std::string& name) {
  for (model::Connection& c : app.connections) {
    if (c.name == name) return c;
  }
  throw std::runtime_error("no connection " + name);
}

model::ArbitratedPort& arbitrated(model::App& app, const std::string& port) {
  for (model::ArbitratedPort& a : app.arbitrated_ports) {
    if (a.port == port) return a;
  }
  throw std::runtime_error("no arbitrated port " + port);
}

}  // namespace arbc::verify::testing
