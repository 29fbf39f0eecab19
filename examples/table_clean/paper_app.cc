#include "examples/table_clean/paper_app.h"

#include <utility>

namespace arbc::table_clean {

using namespace std::chrono_literals;
namespace {

using model::ConnectionKind;
using model::Direction;

model::Port port(std::string name, Direction dir, const char* type) {
  model::Port p;
  p.name = std::move(name);
  p.direction = dir;
  p.type = parse_type(type);
  return p;
}

model::Module module(std::string name, std::vector<model::Port> ports) {
  model::Module m;
  m.name = std::move(name);
  m.ports = std::move(ports);
  return m;
}

Constraint constraint(const std::string& text) { return parse_constraint(text).constraint; }

model::Connection connection(std::string name, std::string from, std::string to,
                             ConnectionKind kind, const std::string& when, std::string monitor) {
  model::Connection c;
  c.name = std::move(name);
  c.source = std::move(from);
  c.destination = std::move(to);
  c.kind = kind;
  c.generated = kind == ConnectionKind::Feed;
  c.constraint = constraint(when);
  c.monitor = monitor.empty() ? "" : "paper_monitors/" + monitor;
  return c;
}

model::Event event(std::string name, std::optional<Nanos> lifetime, std::string source) {
  model::Event e;
  e.name = std::move(name);
  e.lifetime = lifetime;
  e.source = std::move(source);
  return e;
}

}  // namespace

std::string paper_monitors_dir() { return ARBC_TABLE_CLEAN_DIR; }

model::App paper_app() {
  constexpr auto In = Direction::In;
  constexpr auto Out = Direction::Out;
  const char* kCmd = "{verb: string, pos: vec3}";
  model::App app;
  app.name = "table_clean";
  app.description = "The paper's table-cleaning app, hand-written monitors.";
  app.modules = {
      module("ObjectDetector", {port("objects", Out, "list<{pos: vec3, dist: float}>")}),
      module("BucketDetector", {port("bucket", Out, "vec3")}),
      module("FaceDetector", {port("face", Out, "{pos: vec3, certainty: float}")}),
      module("LookAround", {port("gaze", Out, "vec3")}),
      module("HeadControl", {port("gaze", In, "vec3")}),
      module("PickAndPlace", {port("cmd", In, kCmd), port("status", Out, "list<string>")}),
      module("PullObject", {port("cmd", In, kCmd), port("status", Out, "list<string>")}),
      module("Speak", {port("text", In, "string")}),
  };
  app.events = {
      event("e_taken", 500ms, "PickAndPlace.status"),
      event("e_arm_idle", 500ms, "PickAndPlace.status"),
      event("e_pull_idle", 500ms, "PullObject.status"),
      event("e_unreachable", std::nullopt, "ObjectDetector.objects"),
      event("e_face_detected", 1s, "FaceDetector.face"),
      event("act_track", 1s, ""),
  };
  const auto Rule = ConnectionKind::Rule;
  const auto Feed = ConnectionKind::Feed;
  const std::string idle = "e_unreachable and e_arm_idle and e_pull_idle";
  app.connections = {
      connection("take", "ObjectDetector.objects", "PickAndPlace.cmd", Rule,
                 "not e_taken and e_arm_idle and e_pull_idle", "take.lua"),
      connection("put", "BucketDetector.bucket", "PickAndPlace.cmd", Rule, "e_taken and e_arm_idle",
                 "put.lua"),
      connection("feed_pick_status_to_pick", "PickAndPlace.status", "PickAndPlace.cmd", Feed,
                 "false", "pick_status_feed.lua"),
      connection("feed_pull_status_to_pick", "PullObject.status", "PickAndPlace.cmd", Feed, "false",
                 "pull_status_feed.lua"),
      connection("pull", "ObjectDetector.objects", "PullObject.cmd", Rule,
                 "not e_taken and e_arm_idle", "pull.lua"),
      connection("feed_pick_status_to_pull", "PickAndPlace.status", "PullObject.cmd", Feed, "false",
                 "pick_status_feed.lua"),
      connection("track", "FaceDetector.face", "HeadControl.gaze", Rule, idle, "track.lua"),
      connection("search", "LookAround.gaze", "HeadControl.gaze", Rule, idle + " and not act_track",
                 ""),
      connection("feed_objects_to_head", "ObjectDetector.objects", "HeadControl.gaze", Feed,
                 "false", "unreachable_feed.lua"),
      connection("feed_pick_status_to_head", "PickAndPlace.status", "HeadControl.gaze", Feed,
                 "false", "pick_status_feed.lua"),
      connection("feed_pull_status_to_head", "PullObject.status", "HeadControl.gaze", Feed, "false",
                 "pull_status_feed.lua"),
      connection("ask", "FaceDetector.face", "Speak.text", Rule,
                 "e_unreachable and e_face_detected", "ask.lua"),
      connection("feed_objects_to_speak", "ObjectDetector.objects", "Speak.text", Feed, "false",
                 "unreachable_feed.lua"),
      connection("feed_face_to_speak", "FaceDetector.face", "Speak.text", Feed, "false",
                 "face_feed.lua"),
  };
  for (model::Connection& c : app.connections) {
    if (c.name == "ask") c.throttle = 5s;
    if (c.name == "track") {  // by priority: each delivery holds search off for 1 s
      c.activity_event = "act_track";
      c.sets = {"act_track"};
    }
  }
  auto arbitrated = [](std::string port, std::vector<std::string> rules, bool priority) {
    model::ArbitratedPort p;
    p.port = std::move(port);
    p.rules = std::move(rules);
    p.by_priority = priority;
    return p;
  };
  app.arbitrated_ports = {
      arbitrated("PickAndPlace.cmd", {"take", "put"}, false),
      arbitrated("PullObject.cmd", {"pull"}, false),
      arbitrated("HeadControl.gaze", {"track", "search"}, true),
      arbitrated("Speak.text", {"ask"}, false),
  };
  return app;
}

bool set_constraint(model::App& app, const std::string& name, const std::string& text) {
  for (model::Connection& c : app.connections) {
    if (c.name == name && c.kind == ConnectionKind::Rule) {
      c.constraint = constraint(text);
      return true;
    }
  }
  return false;
}

}  // namespace arbc::table_clean
