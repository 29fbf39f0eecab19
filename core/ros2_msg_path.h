// Where ROS 2 `.msg` files are found, and the definitions read from them (issue 41). Each
// folder of the message path holds PKG/msg/NAME.msg, the layout of an installed ROS 2's share/
// folder; the path is, in order, the `--msg-path` folders, ARBC_MSG_PATH (folders separated by
// ':'), then PREFIX/share for each PREFIX of AMENT_PREFIX_PATH (what sourcing a ROS 2 setup
// file sets).
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/ros2_msg.h"

namespace arbc::ros2 {

std::vector<std::string> message_path(const std::vector<std::string>& msg_path_options);

class MsgLibrary {
 public:
  // `builtin`: "pkg/msg/Name" -> .msg text, used when the path has no file for that message.
  explicit MsgLibrary(std::vector<std::string> path,
                      std::map<std::string, std::string> builtin = {});

  // The definition of `full` ("pkg/msg/Name") with every message it uses loaded too (find()
  // then answers for them at once). nullptr with err->message empty when no file on the path
  // and no built-in defines it; nullptr with *err when a file does not parse, a message it
  // uses is not found, or the definitions use each other in a cycle.
  const MsgDefinition* find(const std::string& full, MsgError* err);

  const std::vector<std::string>& path() const { return path_; }

 private:
  const MsgDefinition* load(const std::string& written, MsgError* err);

  std::vector<std::string> path_;
  std::map<std::string, std::string> builtin_;
  std::map<std::string, std::unique_ptr<MsgDefinition>> loaded_;
  std::set<std::string> loading_;  // on the way down: a second visit is a cycle
};

}  // namespace arbc::ros2
