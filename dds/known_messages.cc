#include "dds/known_messages.h"

#include <algorithm>
#include <map>
#include <vector>

#include "core/join.h"
#include "dds/type_name_hint.h"

namespace arbc::dds {

namespace {

struct KnownField {
  std::string name;
  std::string message;  // the field's own message, when it is one; else ""
};

// ROS 2's definitions (common_interfaces): only messages whose fields spec types can carry.
const std::map<std::string, std::vector<KnownField>>& known() {
  static const std::map<std::string, std::vector<KnownField>> messages = {
      {"geometry_msgs/msg/Vector3", {{"x", ""}, {"y", ""}, {"z", ""}}},
      {"geometry_msgs/msg/Point", {{"x", ""}, {"y", ""}, {"z", ""}}},
      {"geometry_msgs/msg/Quaternion", {{"x", ""}, {"y", ""}, {"z", ""}, {"w", ""}}},
      {"geometry_msgs/msg/Pose2D", {{"x", ""}, {"y", ""}, {"theta", ""}}},
      {"geometry_msgs/msg/Twist",
       {{"linear", "geometry_msgs/msg/Vector3"}, {"angular", "geometry_msgs/msg/Vector3"}}},
      {"geometry_msgs/msg/Accel",
       {{"linear", "geometry_msgs/msg/Vector3"}, {"angular", "geometry_msgs/msg/Vector3"}}},
      {"geometry_msgs/msg/Wrench",
       {{"force", "geometry_msgs/msg/Vector3"}, {"torque", "geometry_msgs/msg/Vector3"}}},
      {"geometry_msgs/msg/Pose",
       {{"position", "geometry_msgs/msg/Point"}, {"orientation", "geometry_msgs/msg/Quaternion"}}},
  };
  return messages;
}

std::vector<std::string> names_of(const Type& record) {
  std::vector<std::string> names;
  for (const Field& f : record.fields) names.push_back(f.name);
  return names;
}

// `where`: "" at the top, else "field.subfield" for the message's nested fields.
std::string problem_at(const std::string& what, const Type& spec, const std::string& message,
                       const std::string& where) {
  auto it = known().find(message);
  if (it == known().end() || spec.kind != Type::Kind::Record) return "";
  std::vector<std::string> ours = names_of(spec), theirs;
  for (const KnownField& f : it->second) theirs.push_back(f.name);
  if (ours != theirs) {
    std::vector<std::string> a = ours, b = theirs;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != b) return "";  // other names: not a reordering this can tell
    std::string listed = where.empty() ? "its fields " : "the fields of " + where + " as ";
    return what + " lists " + listed + join(ours) + ", but " + message + " has them in the order " +
           join(theirs) +
           "; the bytes come in the message's order and nothing on the wire names a field, so "
           "each would be read as another: list them in the message's order";
  }
  for (size_t i = 0; i < it->second.size(); ++i) {
    const KnownField& f = it->second[i];
    if (f.message.empty() || !spec.fields[i].type) continue;
    std::string inner = problem_at(what, *spec.fields[i].type, f.message,
                                   where.empty() ? f.name : where + "." + f.name);
    if (!inner.empty()) return inner;
  }
  return "";
}

}  // namespace

std::string field_order_problem(const std::string& name, const Type& spec,
                                const std::string& message) {
  std::string written =
      message.find("::") == std::string::npos ? message : deployment_type_name(message);
  return problem_at("the spec's " + name, spec, written, "");
}

}  // namespace arbc::dds
