// The constants of a ROS 2 message (`uint8 ULTRASOUND=0` in sensor_msgs/msg/Range) as spec
// constants: `use ros2 sensor_msgs/msg/Range;` lets a body write `Range.ULTRASOUND`, as C++
// writes `sensor_msgs::msg::Range::ULTRASOUND`. Each is a ConstDecl named `Range.ULTRASOUND`, a
// name no `const` can take (an identifier has no dot), which sema's field check finds when the
// base of `X.Y` names a type (sema_expr.cc check_field).
#pragma once

#include <optional>
#include <string>

#include "compiler/frontend/ast.h"
#include "core/ros2_msg.h"

namespace arbc::frontend {

// The literal a .msg constant's text is, of a spec type its declared type fits: an int for the
// integer types (in the type's range), a float for float32/float64 (float32: a value that
// rounds to itself), a bool for `true`/`false` (also 1/0, as rosidl reads them), a string for
// string types (quoted or not). nullopt and *why when the text is not such a value.
std::optional<ast::ExprPtr> msg_constant_literal(const ros2::MsgConstant& c, const ast::Loc& at,
                                                 std::string* why);

// The ConstDecl name of constant `constant` of the type `type_name`: "Range.ULTRASOUND".
inline std::string msg_constant_name(const std::string& type_name, const std::string& constant) {
  return type_name + "." + constant;
}

}  // namespace arbc::frontend
