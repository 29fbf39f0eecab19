// Whether a spec's type lays out on the wire as the ROS 2 message the deployment maps it to
// (issue 41: a hand-written record mapped to a ROS 2 name is checked against its definition).
// Nothing on the wire names a field or its width: a record whose `int` stands for an int32, a
// field left out, or two fields of one type in another order, decode into other values or not
// at all, and every rule reads them. The message's definition is its `.msg` file on the
// message path (core/ros2_msg_path.h), else the built-in definitions of common messages
// (core/ros2_known_messages.h); a message found in neither is not checked.
#pragma once

#include <string>

#include "core/ros2_msg_path.h"
#include "core/type.h"

namespace arbc::dds {

// What is wrong with `spec` (the spec's type `name`) standing for `message` ("pkg/msg/Name" or
// its DDS name); "" when it lays out as the message, or the message is not found. A `.msg` file
// that does not parse, or uses a message not found, is a problem too.
std::string layout_problem(const std::string& name, const Type& spec, const std::string& message,
                           ros2::MsgLibrary& library);

}  // namespace arbc::dds
