// The deployment file of a DDS run (`arbc run --transport dds --deploy FILE`): the DDS domain,
// ROS 2 naming, the topic of each port and the wire name of each named type, the history
// depth. Its JSON Schema is docs/deployment.schema.json; docs/distributed.md explains each key.
//
//   {"domain": 7, "ros2": true,
//    "topics": {"Base.cmd_vel": "/cmd_vel"},
//    "types": {"Twist": "geometry_msgs/msg/Twist", "vec3": "geometry_msgs/msg/Vector3"},
//    "qos": {"depth": 100}}
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "core/app_model.h"

namespace arbc::dds {

// History depth of every reader and writer (reliable, keep-last) unless the file says another:
// one second of a 100 Hz stream, ten times ROS 2's default of 10, so that a mediator that is
// busy for a moment (a burst of three sources, a descheduled process) loses nothing.
inline constexpr int kDefaultDepth = 100;

struct Deployment {
  std::string path;  // the file read ("" without --deploy), for messages
  std::optional<int> domain;
  bool ros2 = false;
  std::map<std::string, std::string> topics;  // "Module.port" -> topic as written
  std::map<std::string, std::string> types;   // named type (or "vec3", ...) -> "pkg/msg/Name"
  int depth = kDefaultDepth;
};

// Parses a deployment file's text; `path` names it in messages. False with *error (the file,
// the key, what is wrong, what to do) on malformed JSON, an unknown key or a value of the
// wrong kind.
bool parse_deployment(std::string_view text, const std::string& path, Deployment* out,
                      std::string* error);
// Reads and parses the file at `path`.
bool read_deployment(const std::string& path, Deployment* out, std::string* error);
// Checks the file against the app: every `topics` key is a port of the app, every `types` key
// a named type of the app or a built-in type name, no two ports share a topic.
bool check_deployment(const Deployment& d, const model::App& app, std::string* error);

}  // namespace arbc::dds
