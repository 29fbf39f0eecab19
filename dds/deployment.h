// The deployment file of a DDS run (`arbc run --transport dds --deploy FILE`): the DDS domain,
// ROS 2 naming, the topic of each port and the wire name of each named type, the history
// depth. Its JSON Schema is docs/deployment.schema.json; docs/distributed.md explains each key.
//
//   {"domain": 7, "ros2": true,
//    "topics": {"Base.cmd_vel": "/cmd_vel"},
//    "types": {"Twist": "geometry_msgs/msg/Twist", "vec3": "geometry_msgs/msg/Vector3"},
//    "qos": {"depth": 100, "ports": {"Bumper.state": {"reliability": "best_effort"}}},
//    "status": {"diagnostics": "/diagnostics", "topics": {"Base.cmd_vel": "/mux/active"}}}
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/app_model.h"
#include "core/diagnostic.h"

namespace arbc::dds {

// History depth of every reader and writer (reliable, keep-last) unless the file says another:
// one second of a 100 Hz stream, ten times ROS 2's default of 10, so that a mediator that is
// busy for a moment (a burst of three sources, a descheduled process) loses nothing.
inline constexpr int kDefaultDepth = 100;

// How one port's topic is read or written where it is not reliable and volatile: DDS matches a
// reliable reader with no best-effort writer (ROS 2's sensor-data profile), and a volatile
// writer with no transient-local reader (a latched topic), and then nothing flows.
struct PortQos {
  bool best_effort = false;      // "reliability": "best_effort"
  bool transient_local = false;  // "durability": "transient_local"
};

struct Deployment {
  std::string path;  // the file read ("" without --deploy), for messages
  std::string text;  // its text, to place what check_deployment finds in it
  std::optional<int> domain;
  bool ros2 = false;
  std::map<std::string, std::string> topics;  // "Module.port" -> topic as written
  std::map<std::string, std::string> types;   // named type (or "vec3", ...) -> "pkg/msg/Name"
  int depth = kDefaultDepth;
  std::map<std::string, PortQos> port_qos;  // "Module.port" -> "qos": {"ports": ...}
  // `--msg-path` folders, searched before ARBC_MSG_PATH and AMENT_PREFIX_PATH for the `.msg`
  // files `types` are checked against (core/ros2_msg_path.h).
  std::vector<std::string> msg_path;
  // The live status (docs/distributed.md#live-status): on unless the file says "status": false;
  // the topic of the DiagnosticArray and each arbitrated port's status topic, where the file
  // gives them ("status": {"diagnostics": "/diagnostics", "topics": {"Base.cmd_vel": "/mux"}}).
  bool status = true;
  std::string diagnostics_topic = "/diagnostics";
  std::map<std::string, std::string> status_topics;

  PortQos qos_of(const std::string& port) const {
    auto it = port_qos.find(port);
    return it == port_qos.end() ? PortQos{} : it->second;
  }
};

// Errors are diagnostics at the place in the file they are about
// (docs/design.md#reporting-errors): `file:line:col: error: what is wrong`, the line and column
// of the offending key or value (of the offending character, for malformed JSON), one per
// problem, in the file's order.

// Parses a deployment file's text; `path` names it in messages. False with *errors on malformed
// JSON, an unknown key or a value of the wrong kind.
bool parse_deployment(std::string_view text, const std::string& path, Deployment* out,
                      std::vector<Diagnostic>* errors);
// Reads and parses the file at `path` (a missing file or a directory is an error at the file).
bool read_deployment(const std::string& path, Deployment* out, std::vector<Diagnostic>* errors);
// Checks the file against the app: every `topics` key is a port of the app, every `types` key
// a named type of the app or a built-in type name that lays out as the ROS 2 message it stands
// for, when its definition is found (dds/msg_layout.h), every "qos" "ports" key a port,
// no two ports
// share a topic (a topic the file gives is not another port's default either).
bool check_deployment(const Deployment& d, const model::App& app, std::vector<Diagnostic>* errors);
// The diagnostics as "file:line:col: message" lines, for an error that is one string.
std::string deployment_errors_text(const std::vector<Diagnostic>& errors);

// The topic of a port ("Module.port") on the wire: the deployment's, else "Module/port"; with
// ros2, "rt" + "/topic" ("rt/Module/port" by default).
std::string wire_topic(const Deployment& d, const std::string& qualified);

}  // namespace arbc::dds
