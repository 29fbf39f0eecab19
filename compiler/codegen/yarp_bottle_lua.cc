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
    case Type::Kind::Float: {
      // A sized number carries its width (yarp_bottle.lua checks the range on reading); int64
      // and float64 stay as before sized types, so older monitors' text is unchanged.
      std::string kind = t.kind == Type::Kind::Int ? "int" : "float";
      if (!t.narrow()) return "{ kind = \"" + kind + "\" }";
      return "{ kind = \"" + kind + "\", bits = " + std::to_string(t.bits) +
             (t.is_unsigned ? ", unsigned = true" : "") + " }";
    }
    case Type::Kind::String:
      if (t.size > 0) return "{ kind = \"string\", size = " + std::to_string(t.size) + " }";
      return "{ kind = \"string\" }";
    case Type::Kind::Vec3:
      return "{ kind = \"vec3\" }";
    case Type::Kind::List:
      return "{ kind = \"list\", element = " + yarp_type_descriptor(*t.element) +
             (t.size > 0 ? ", size = " + std::to_string(t.size) : "") +
             (t.fixed ? ", fixed = true" : "") + " }";
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
