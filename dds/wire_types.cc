#include "dds/wire_types.h"

#include <fastrtps/types/DynamicTypeBuilder.h>
#include <fastrtps/types/DynamicTypeBuilderFactory.h>
#include <fastrtps/types/DynamicTypeBuilderPtr.h>

#include <cstdint>
#include <string>

namespace arbc::dds {

namespace ft = eprosima::fastrtps::types;

namespace {

// Fast-DDS 2.9's dynamic types turn a bound of 0 into 100 elements (255 characters for a
// string); the largest bound stands for "unbounded". The bytes on the wire are those of an IDL
// unbounded sequence or string: a bound is not part of the CDR encoding.
constexpr uint32_t kUnbounded = INT32_MAX;

// The name of a scalar's wrapper struct: ROS 2's std_msgs layout and names (std_msgs/msg/Int32,
// UInt8, Float32, ...).
std::string scalar_message(const Type& t) {
  switch (t.kind) {
    case Type::Kind::Bool:
      return "Bool";
    case Type::Kind::Int:
      return std::string(t.is_unsigned ? "UInt" : "Int") + std::to_string(t.bits);
    case Type::Kind::Float:
      return "Float" + std::to_string(t.bits);
    default:
      return "String";
  }
}

// The key of a built-in type in the deployment's "types": its canonical spelling ("int",
// "uint8", "float32").
std::string builtin_key(const Type& t) { return t.to_string(); }

// A number type on the wire: its CDR width (an int8 or a uint8 is one octet, which Fast-DDS 2.9's
// dynamic types call a byte; wire_values.cc reads int8 back with its sign).
ft::DynamicType_ptr number(const Type& t) {
  ft::DynamicTypeBuilderFactory* f = ft::DynamicTypeBuilderFactory::get_instance();
  if (t.kind == Type::Kind::Float)
    return t.bits == 32 ? f->create_float32_type() : f->create_float64_type();
  switch (t.bits) {
    case 8:
      return f->create_byte_type();
    case 16:
      return t.is_unsigned ? f->create_uint16_type() : f->create_int16_type();
    case 32:
      return t.is_unsigned ? f->create_uint32_type() : f->create_int32_type();
    default:
      return t.is_unsigned ? f->create_uint64_type() : f->create_int64_type();
  }
}

ft::DynamicType_ptr scalar(const Type& t) {
  ft::DynamicTypeBuilderFactory* f = ft::DynamicTypeBuilderFactory::get_instance();
  switch (t.kind) {
    case Type::Kind::Bool:
      return f->create_bool_type();
    case Type::Kind::Int:
    case Type::Kind::Float:
      return number(t);
    default:
      return f->create_string_type(t.size > 0 ? static_cast<uint32_t>(t.size) : kUnbounded);
  }
}

bool is_scalar(Type::Kind k) {
  return k == Type::Kind::Bool || k == Type::Kind::Int || k == Type::Kind::Float ||
         k == Type::Kind::String;
}

}  // namespace

WireNaming::WireNaming(const model::App& app, const Deployment& deployment)
    : app_(app), deployment_(deployment) {}

std::string WireNaming::topic(const std::string& qualified) const {
  return wire_topic(deployment_, qualified);
}

std::string WireNaming::mangle(const std::string& written) const {
  if (written.find("::") != std::string::npos || written.find('/') == std::string::npos)
    return written;
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t slash = written.find('/');; slash = written.find('/', start)) {
    parts.push_back(written.substr(start, slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  std::string out;
  for (size_t i = 0; i + 1 < parts.size(); ++i) out += parts[i] + "::";
  return deployment_.ros2 ? out + "dds_::" + parts.back() + "_" : out + parts.back();
}

std::string WireNaming::spec_name(const Type& t) const {
  if (t.kind != Type::Kind::Record && t.kind != Type::Kind::List) return {};
  std::string text = t.to_string();
  for (const model::NamedType& n : app_.types) {
    if (n.type && n.type->to_string() == text) return n.name;
  }
  return {};
}

// A spec name `Cmd` is `<app>::msg::dds_::Cmd_` with ros2 (as if the app were a ROS package),
// `<app>::Cmd` without; a type `use ros2` declared is its message's name; the deployment's
// "types" overrides any of them.
std::string WireNaming::struct_name(const Type& t, const std::string& anonymous) const {
  if (t.kind == Type::Kind::Vec3) {
    auto it = deployment_.types.find("vec3");
    if (it != deployment_.types.end()) return mangle(it->second);
    return deployment_.ros2 ? mangle("geometry_msgs/msg/Vector3") : "arbc::Vec3";
  }
  std::string name = spec_name(t);
  auto it = name.empty() ? deployment_.types.end() : deployment_.types.find(name);
  if (it != deployment_.types.end()) return mangle(it->second);
  for (const model::NamedType& n : app_.types) {
    if (!name.empty() && n.name == name && !n.ros2.empty()) return mangle(n.ros2);
  }
  std::string local = name.empty() ? anonymous : name;
  return deployment_.ros2 ? mangle(app_.name + "/msg/" + local) : app_.name + "::" + local;
}

std::string WireNaming::wrapper_name(const Type& t, const std::string& anonymous) const {
  if (!is_scalar(t.kind)) return struct_name(t, anonymous);
  auto it = deployment_.types.find(builtin_key(t));
  if (it != deployment_.types.end()) return mangle(it->second);
  std::string message = scalar_message(t);
  return deployment_.ros2 ? mangle("std_msgs/msg/" + message) : "arbc::" + message;
}

std::shared_ptr<const WireType> WireNaming::port_type(const std::string& module,
                                                      const std::string& port, const TypePtr& type,
                                                      std::string* error) {
  auto wire = std::make_shared<WireType>();
  wire->type = type;
  std::string anonymous = module + "_" + port;
  if (type->kind == Type::Kind::Record || type->kind == Type::Kind::Vec3) {
    wire->dynamic = build(*type, anonymous, error);
    if (!wire->dynamic) return nullptr;
    wire->name = wire->dynamic->get_name();
  } else {
    wire->wrapped = true;
    wire->name = wrapper_name(*type, anonymous);
    std::string local = spec_name(*type);
    ft::DynamicType_ptr data = build(*type, (local.empty() ? anonymous : local) + "_data", error);
    if (!data) return nullptr;
    wire->dynamic =
        build_struct(wire->name, "{data: " + type->to_string() + "}", {{"data", data}}, error);
    if (!wire->dynamic) return nullptr;
  }
  wire->signature = structs_.at(wire->name).signature;
  return wire;
}

// `anonymous` names the struct of t when neither the spec nor the deployment does; the
// anonymous records inside a struct are named after it and their field (`Cmd_pos`).
ft::DynamicType_ptr WireNaming::build(const Type& t, const std::string& anonymous,
                                      std::string* error) {
  if (is_scalar(t.kind)) return scalar(t);
  ft::DynamicTypeBuilderFactory* f = ft::DynamicTypeBuilderFactory::get_instance();
  if (t.kind == Type::Kind::List) {
    ft::DynamicType_ptr element = build(*t.element, anonymous, error);
    if (!element) return {};
    if (t.fixed) return fixed_list(t, element, anonymous, error);
    // list<T, N> is a bounded sequence: the same bytes as a sequence (the bound is not on the
    // wire; wire_values.cc checks it).
    uint32_t n = static_cast<uint32_t>(t.size);
    ft::DynamicTypeBuilder_ptr b(f->create_sequence_builder(element, n ? n : kUnbounded));
    return b->build();
  }
  std::vector<std::pair<std::string, ft::DynamicType_ptr>> members;
  if (t.kind == Type::Kind::Vec3) {
    for (const char* axis : {"x", "y", "z"}) members.push_back({axis, f->create_float64_type()});
    return build_struct(struct_name(t, anonymous), "vec3", members, error);
  }
  std::string local = spec_name(t);
  if (local.empty()) local = anonymous;
  for (const Field& field : t.fields) {
    ft::DynamicType_ptr m = build(*field.type, local + "_" + field.name, error);
    if (!m) return {};
    members.push_back({field.name, m});
  }
  return build_struct(struct_name(t, anonymous), t.to_string(), members, error);
}

// T[N] as a struct of N members e0 ... eN-1: the bytes of an IDL array T[N] (the elements, each
// at its alignment, no length). Not Fast-DDS 2.9's array type, whose DynamicData keeps an
// element equal to the default as no element, so a -0.0 went out as 0.0 (tests/dds/matrix).
ft::DynamicType_ptr WireNaming::fixed_list(const Type& t, const ft::DynamicType_ptr& element,
                                           const std::string& anonymous, std::string* error) {
  std::vector<std::pair<std::string, ft::DynamicType_ptr>> members;
  for (int i = 0; i < t.size; ++i) members.push_back({"e" + std::to_string(i), element});
  return build_struct("arbc::array::" + anonymous, t.to_string(), members, error);
}

// Builds (or reuses) the struct `name` whose spec structure is `structure`. Two different
// structures under one name are an error: a reader could not decode the other's samples. (The
// names of nested structs follow from the outer one, so equal text means equal structs.)
ft::DynamicType_ptr WireNaming::build_struct(
    const std::string& name, const std::string& structure,
    const std::vector<std::pair<std::string, ft::DynamicType_ptr>>& members, std::string* error) {
  std::string signature = name + " " + structure;
  auto it = structs_.find(name);
  if (it != structs_.end()) {
    if (it->second.signature == signature) return it->second.type;
    *error = "two different types would both be " + name + " on the wire (" + it->second.signature +
             ", and " + signature + "); give them different names in the deployment's \"types\"";
    return {};
  }
  ft::DynamicTypeBuilderFactory* f = ft::DynamicTypeBuilderFactory::get_instance();
  ft::DynamicTypeBuilder_ptr b(f->create_struct_builder());
  b->set_name(name);
  for (size_t i = 0; i < members.size(); ++i)
    b->add_member(static_cast<ft::MemberId>(i), members[i].first, members[i].second);
  ft::DynamicType_ptr type = b->build();
  structs_[name] = {signature, type};
  return type;
}

}  // namespace arbc::dds
