// The definitions of the ROS 2 messages spec records most often stand for, as their `.msg`
// files write them (facts of the messages' layouts, from ROS 2's common_interfaces and
// rcl_interfaces): what the deployment's `types` are checked against when no `.msg` file on the
// message path defines the message (dds/msg_layout.h), and what `use ros2` reads then
// (compiler/frontend/ros2_uses.h).
#pragma once

#include <map>
#include <string>

namespace arbc::ros2 {

// "pkg/msg/Name" -> the text of its .msg file.
const std::map<std::string, std::string>& known_message_texts();

}  // namespace arbc::ros2
