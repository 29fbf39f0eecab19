// ROS 2 message definitions: the `.msg` files of ROS 2 packages (rosidl's interface definition
// language: one `TYPE NAME [DEFAULT]` field or `TYPE NAME=VALUE` constant per line, `#`
// comments), read as they are, so that arbc can compare a spec's record with the message it
// stands for (dds/msg_layout.h) and, later, declare types from them (issue 41).
//
// Types: the primitives bool byte char float32 float64 int8 uint8 int16 uint16 int32 uint32
// int64 uint64 string wstring, bounded strings `string<=N`, other messages `Name` (same
// package) or `pkg/Name`, each optionally an array: `T[]` (a sequence), `T[<=N]` (a bounded
// sequence), `T[N]` (a fixed array).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arbc::ros2 {

struct MsgType {
  enum class Array { None, Sequence, BoundedSequence, Fixed };
  std::string name;  // a primitive ("float32"), or a message "pkg/msg/Name"
  bool primitive = true;
  int string_bound = 0;  // string<=N, wstring<=N; 0: unbounded
  Array array = Array::None;
  int array_size = 0;  // the N of T[N] or T[<=N]

  // As a .msg file writes it: "int32", "string<=8", "geometry_msgs/Vector3[]".
  std::string text() const;
};

struct MsgField {
  std::string name;
  MsgType type;
  std::string default_text;  // as written after the name; "" when none
  int line = 0, column = 0;  // of the field's type, from 1
};

struct MsgConstant {
  std::string name;
  MsgType type;
  std::string value;  // as written after `=`
  int line = 0, column = 0;
};

struct MsgDefinition {
  std::string package, name;  // "geometry_msgs", "Twist"
  std::string file;           // where it was read ("" for a built-in definition)
  std::vector<MsgField> fields;
  std::vector<MsgConstant> constants;

  std::string full_name() const { return package + "/msg/" + name; }
};

struct MsgError {
  std::string file;
  int line = 0, column = 0;
  std::string message;  // what is wrong and what to do
};

// "geometry_msgs/msg/Twist", "geometry_msgs/Twist", or a DDS name
// ("geometry_msgs::msg::dds_::Twist_") -> {"geometry_msgs", "Twist"}; nullopt for anything else.
std::optional<std::pair<std::string, std::string>> split_message_name(std::string_view name);

// Parses the text of PACKAGE/msg/NAME.msg (`file` names it in errors). Message types without a
// package are `package`'s. nullopt and *err at the first line that is not a field, a constant,
// a comment or blank.
std::optional<MsgDefinition> parse_msg(std::string_view text, const std::string& package,
                                       const std::string& name, const std::string& file,
                                       MsgError* err);

}  // namespace arbc::ros2
