#include "compiler/codegen/yarp_bottle_lua.h"

#include <string_view>

#include "compiler/codegen/lua_text.h"

namespace arbc::embedded {
// yarp_bottle.lua, embedded at build time (arbc_embed_text), where luac -p and the gates see it.
extern const std::string_view kYarpBottleLua;
}  // namespace arbc::embedded

namespace arbc::codegen {

std::string yarp_type_descriptor(const Type& t) {
  switch (t.kind) {
    case Type::Kind::Bool:
      return "{ kind = \"bool\" }";
    case Type::Kind::Int:
      return "{ kind = \"int\" }";
    case Type::Kind::Float:
      return "{ kind = \"float\" }";
    case Type::Kind::String:
      return "{ kind = \"string\" }";
    case Type::Kind::Vec3:
      return "{ kind = \"vec3\" }";
    case Type::Kind::List:
      return "{ kind = \"list\", element = " + yarp_type_descriptor(*t.element) + " }";
    case Type::Kind::Record: {
      std::string fields, order;
      for (const Field& f : t.fields) {
        fields +=
            (fields.empty() ? "" : ", ") + lua_table_key(f.name) + yarp_type_descriptor(*f.type);
        order += (order.empty() ? "" : ", ") + lua_string(f.name);
      }
      return "{ kind = \"record\", fields = { " + fields + " }, order = { " + order + " } }";
    }
  }
  return "{ kind = \"string\" }";
}

std::string yarp_bottle_lua() { return std::string(embedded::kYarpBottleLua); }

}  // namespace arbc::codegen
