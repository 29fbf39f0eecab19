// The live status on DDS as ROS 2 messages (issue 42, docs/distributed.md#live-status): each
// arbitrated port's runtime/port_status.h as a diagnostic_msgs/msg/DiagnosticStatus (its latched
// status topic) and all of them as a diagnostic_msgs/msg/DiagnosticArray (/diagnostics, read by
// rqt_robot_monitor and Foxglove). The spec types here lay out as those messages' .msg files
// (core/ros2_known_messages.cc; status_types_test.cc holds them to it), and the values fill them.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "runtime/port_status.h"

namespace arbc::dds {

// The spec types, each named as ROS 2 names it (NamedType::ros2), so that WireNaming gives the
// wire names ROS 2 programs use ("diagnostic_msgs::msg::dds_::DiagnosticArray_").
struct StatusTypes {
  std::vector<model::NamedType> named;  // Time, Header, KeyValue, DiagnosticStatus, DiagnosticArray
  TypePtr status, array;
};
const StatusTypes& status_types();

// The default topic of a port's status ("Base.cmd_vel" of app "mux"):
// "/arbc/mux/status/Base/cmd_vel"; the deployment's "status" "topics" overrides it.
std::string default_status_topic(const std::string& app, const std::string& port);

// A status topic as written ("/diagnostics") on the wire as ROS 2 names it ("rt/diagnostics"),
// whatever the deployment's "ros2" says: the status is for ROS 2 tools. One definition for the
// mediator that writes it and `arbc status` that reads it.
std::string status_wire_topic(const std::string& written);

// A port's latched status: level, name "APP: PORT", message (p.message), and one key per rule
// with its state ("selected", or why it is not selected, or "may deliver"), after the key
// "selected" (the selected rule, "" when none). Nothing in it changes with time alone, so it is
// written again only when the port's state changes.
Value latched_status_value(const PortStatus& p, const std::string& app);

// The /diagnostics message at `t` (run time; `stamp`: its ROS 2 time): a status per port with
// its rules and counters (arrived, delivered, each drop reason seen, the last delivery's age).
Value diagnostic_array_value(const std::vector<PortStatus>& ports, const std::string& app, Nanos t,
                             Nanos stamp);

// A status as a line, read back from its message (`arbc status`): "teleop: Base.cmd_vel  OK  nav
// selected | joy: may deliver  [30 of 41 delivered; dropped not-selected 10; last delivery 400ms
// ago by nav]".
std::string status_line(const Value& status);

}  // namespace arbc::dds
