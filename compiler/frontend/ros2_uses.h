// `use ros2 PKG/msg/NAME;` (docs/language.md#ros-2-messages): the message's type read from its
// `.msg` file, not retyped. Before sema, each used message and every message it uses become a
// `type` declaration of the spec (ast::TypeDecl with `ros2` set), so every later stage (sema,
// lowering, app.json, the DDS wire types, the LSP) sees an ordinary record type that also knows
// which ROS 2 message it is.
//
// The definitions come from the message path (core/ros2_msg_path.h: ARBC_MSG_PATH, which
// `--msg-path` extends, then AMENT_PREFIX_PATH), else from arbc's built-in list of common
// messages (core/ros2_known_messages.h), so a machine without ROS 2 can still mediate them.
//
// Names: a used message takes its own name (`TwistStamped`); a message it uses takes its name
// too unless the spec already has a type of that name, then PKG_NAME (`geometry_msgs_Vector3`).
#pragma once

#include <string>
#include <vector>

#include "compiler/frontend/ast.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

// Appends to spec.types a declaration for each message `spec.uses` needs; errors (id
// "ros2-message") go to `out`, at the `use`, with a note at the .msg file's line. `first` are
// folders searched before the message path (`arbc import ros2-msg`'s own).
void declare_ros2_uses(ast::Spec& spec, std::vector<Diagnostic>& out,
                       const std::vector<std::string>& first = {});

}  // namespace arbc::frontend
