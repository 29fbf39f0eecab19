#include "core/builtins.h"

namespace arbc {

const BuiltinInfo* find_builtin(std::string_view name) {
  for (const BuiltinInfo& b : kBuiltins)
    if (b.name == name) return &b;
  return nullptr;
}

const BuiltinInfo* builtin_info(Builtin id) {
  for (const BuiltinInfo& b : kBuiltins)
    if (b.id == id) return &b;
  return nullptr;
}

std::string builtin_names_text() {
  std::string out;
  for (const BuiltinInfo& b : kBuiltins) {
    if (!out.empty()) out += ", ";
    out += b.name;
  }
  return out;
}

}  // namespace arbc
