// Spec types as DDS types, built at run time with Fast-DDS dynamic types, and the names ports and
// types have on the wire (docs/distributed.md#types-on-the-wire).
//
//   bool -> boolean   int -> int64   float -> float64   string -> string
//   vec3 -> struct {float64 x, y, z} (the layout of geometry_msgs/msg/Vector3 and Point)
//   list<T> -> sequence<T> (unbounded)   record -> struct, fields in declaration order
// A DDS topic carries a struct, so a port whose type is not a record or vec3 travels as a
// struct with one field `data` (the layout of ROS 2's std_msgs/msg/String, Bool, Int64, ...).
#pragma once

#include <fastrtps/types/DynamicType.h>
#include <fastrtps/types/DynamicTypePtr.h>

#include <map>
#include <memory>
#include <string>

#include "core/app_model.h"
#include "dds/deployment.h"

namespace arbc::dds {

// How the values of one port travel.
struct WireType {
  std::string name;  // the DDS type name, e.g. "geometry_msgs::msg::dds_::Twist_"
  eprosima::fastrtps::types::DynamicType_ptr dynamic;
  TypePtr type;          // the port's spec type
  bool wrapped = false;  // the value is the struct's one field `data`
  // The structure as text, to tell two types apart under one name: "Name{data: list<string>}".
  std::string signature;
};

// Names and builds wire types and topics for one app and deployment. Types are built once per
// DDS name and shared by every port that uses them.
class WireNaming {
 public:
  WireNaming(const model::App& app, const Deployment& deployment);

  // The topic of a port ("Module.port") on the wire: the deployment's, else "Module/port";
  // with ros2, "rt" + "/topic" ("rt/Module/port" by default).
  std::string topic(const std::string& qualified) const;
  // The wire type of a port. Null with *error when two different types would have one name.
  std::shared_ptr<const WireType> port_type(const std::string& module, const std::string& port,
                                            const TypePtr& type, std::string* error);
  // "pkg/msg/Name" -> "pkg::msg::dds_::Name_" with ros2, else "pkg::msg::Name"; a name with
  // "::" is used as written.
  std::string mangle(const std::string& written) const;
  // The spec's name for a record or list type (the first named type with its structure).
  std::string spec_name(const Type& t) const;

 private:
  // The DDS name of a struct for spec type t: mapped, derived from its spec name, or from
  // `anonymous` (a Module_port_field path) when the spec did not name it.
  std::string struct_name(const Type& t, const std::string& anonymous) const;
  std::string wrapper_name(const Type& t, const std::string& anonymous) const;
  eprosima::fastrtps::types::DynamicType_ptr build(const Type& t, const std::string& anonymous,
                                                   std::string* error);
  eprosima::fastrtps::types::DynamicType_ptr fixed_list(
      const Type& t, const eprosima::fastrtps::types::DynamicType_ptr& element,
      const std::string& anonymous, std::string* error);
  eprosima::fastrtps::types::DynamicType_ptr build_struct(
      const std::string& name, const std::string& signature,
      const std::vector<std::pair<std::string, eprosima::fastrtps::types::DynamicType_ptr>>&
          members,
      std::string* error);

  const model::App& app_;
  const Deployment& deployment_;
  struct Built {
    std::string signature;
    eprosima::fastrtps::types::DynamicType_ptr type;
  };
  std::map<std::string, Built> structs_;  // by DDS name
};

}  // namespace arbc::dds
