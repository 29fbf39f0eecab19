// `arbc import ros2-msg FILE.msg|DIR -o types.spec`: ROS 2 message definitions as `type`
// declarations, for a team that wants the records in its spec rather than `use ros2`
// (docs/language.md#ros-2-messages). The records are the ones `use ros2` declares
// (compiler/frontend/ros2_uses.h), printed: one conversion from .msg to spec types.
#pragma once

#include <string>
#include <vector>

#include "core/diagnostic.h"

namespace arbc::ros2_import {

struct MsgImport {
  bool ok = false;
  std::vector<Diagnostic> diagnostics;
  std::string spec;  // the `type` declarations, each message after those it uses
};

// `input`: one PKG/msg/NAME.msg file, a package folder (PKG, holding msg/), or a folder of
// packages. The folder above the packages is searched first for the messages they use, then
// the message path, then arbc's built-in definitions.
MsgImport import_ros2_messages(const std::string& input);

}  // namespace arbc::ros2_import
