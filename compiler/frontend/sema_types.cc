// Sema's types and port references: type expressions to structural types (named types
// expanded, fields declared once) and `Module.port` resolved with its direction and use.
#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/type_rules.h"
#include "core/join.h"
#include "core/suggest.h"

namespace arbc::frontend {

using namespace ast;

namespace {

const TypePtr& scalar_type(TypeExpr::Kind kind) {
  static const TypePtr kTypes[] = {Type::scalar(Type::Kind::Bool), Type::scalar(Type::Kind::Int),
                                   Type::scalar(Type::Kind::Float),
                                   Type::scalar(Type::Kind::String),
                                   Type::scalar(Type::Kind::Vec3)};
  return kTypes[static_cast<int>(kind)];
}

}  // namespace

// ---- types --------------------------------------------------------------------------------

TypePtr Sema::resolve_type(TypeExpr& t) {
  switch (t.kind) {
    case TypeExpr::Kind::Bool:
    case TypeExpr::Kind::Int:
    case TypeExpr::Kind::Float:
    case TypeExpr::Kind::Vec3:
      t.resolved = scalar_type(t.kind);
      break;
    case TypeExpr::Kind::String:
      t.resolved = t.size > 0 ? Type::bounded_string(t.size) : scalar_type(t.kind);
      break;
    case TypeExpr::Kind::List: {
      TypePtr element = resolve_type(*t.element);
      if (element) t.resolved = Type::sized_list(element, t.size, t.fixed);
      break;
    }
    case TypeExpr::Kind::Record: {
      std::vector<Field> fields;
      bool ok = true;
      for (size_t i = 0; i < t.fields.size(); ++i) {
        for (size_t j = 0; j < i; ++j)
          if (t.fields[j].first == t.fields[i].first)
            error(t.field_locs[i],
                  "field '" + t.fields[i].first + "' is declared twice" + kRenameOne,
                  diag::Duplicate);
        TypePtr f = resolve_type(*t.fields[i].second);
        if (!f) ok = false;
        fields.push_back({t.fields[i].first, f});
      }
      if (ok) t.resolved = Type::record(std::move(fields));
      break;
    }
    case TypeExpr::Kind::Named:
      t.resolved = resolve_named_type(t);
      break;
  }
  return t.resolved;
}

TypePtr Sema::resolve_type_decl(TypeDecl& decl) {
  if (types_done_.count(&decl)) return decl.type.resolved;
  if (types_active_.count(&decl)) {
    // A message is a finite value that the proof and the Lua monitors copy whole: no type
    // may contain itself, not even through a list.
    error(decl.loc,
          "type '" + decl.name +
              "' is defined in terms of itself: a type cannot contain itself, even through a "
              "list or another type; give the inner value a type of its own",
          diag::TypeCycle);
    types_done_.insert(&decl);
    return nullptr;
  }
  types_active_.insert(&decl);
  TypePtr t = resolve_type(decl.type);
  types_active_.erase(&decl);
  types_done_.insert(&decl);
  // A named record or list keeps its name in messages ("Cmd", not its fields). Only types
  // this declaration creates: an alias (`type A = B;`, `type A = vec3;`) shares B's object.
  bool creates = decl.type.kind == TypeExpr::Kind::Record || decl.type.kind == TypeExpr::Kind::List;
  bool registered = types_.count(decl.name) && types_.at(decl.name) == &decl;
  if (t && creates && registered && !type_names_.count(t.get())) type_names_[t.get()] = decl.name;
  return t;
}

TypePtr Sema::resolve_named_type(TypeExpr& t) {
  auto it = types_.find(t.name);
  if (it == types_.end() && spec_.failed_uses.count(t.name)) return nullptr;  // said at the use
  if (it == types_.end()) {
    // The number types by any spelling (core/number_types.def): `int32`, `byte`, `float64`.
    if (TypePtr number = Type::number(t.name)) return number;
    std::vector<std::string> names = {"bool", "string", "vec3", "list"};
    for (const std::string& n : Type::number_names()) names.push_back(n);
    for (auto& [name, decl] : types_) names.push_back(name);
    unknown(t.loc,
            "unknown type '" + t.name +
                "': the types are bool, int, float, the sized numbers (int8 to int64, uint8 to "
                "uint64, float32, float64, byte, char), string, string<N>, vec3, list<T>, "
                "list<T, N>, T[N], records and declared type names",
            diag::UnknownType, t.name, names);
    return nullptr;
  }
  return resolve_type_decl(*it->second);
}

// ---- port references ----------------------------------------------------------------------

bool Sema::resolve_port(PortRef& ref, const char* role, const std::string& use) {
  auto found = modules_.find(ref.module);
  ref.module_decl = found == modules_.end() ? nullptr : found->second;
  if (!ref.module_decl) {
    std::vector<std::string> names;
    for (const ModuleDecl& m : spec_.modules) names.push_back(m.name);
    // At the module's name alone: an editor's quick fix replaces exactly what is underlined.
    Diagnostic& d = unknown(ref.module_loc, "unknown module '" + ref.module + "'",
                            diag::UnknownModule, ref.module, names);
    if (d.notes.empty()) {  // no close name: what there is, and how to add it
      Diagnostic note;
      note.severity = Severity::Note;
      note.message = "declare it: `module " + ref.module + " { in|out PORT: TYPE; ... }`";
      if (!names.empty() && names.size() <= 10)
        note.message += "; the modules declared are " + join(names, ", ", " and ");
      d.notes.push_back(std::move(note));
    }
    return false;
  }
  ref.port_decl = ref.module_decl->find_port(ref.port);
  if (!ref.port_decl) {
    std::vector<std::string> names, listed;
    for (const PortDecl& p : ref.module_decl->ports) {
      names.push_back(p.name);
      listed.push_back("'" + p.name + "' (" + (p.direction == model::Direction::In ? "in" : "out") +
                       ")");
    }
    Diagnostic& d =
        unknown(ref.port_loc, "module '" + ref.module + "' has no port '" + ref.port + "'",
                diag::UnknownPort, ref.port, names);
    if (d.notes.empty() && !listed.empty()) {  // nothing close (`velocity` for `vel`): list them
      Diagnostic note;
      note.severity = Severity::Note;
      note.message = (listed.size() == 1 ? "the only port of " + ref.module + " is "
                                         : "the ports of " + ref.module + " are ") +
                     join(listed, ", ", " and ");
      d.notes.push_back(std::move(note));
    }
    return false;
  }
  std::string role_s = role;
  if (role_s == "source" && ref.port_decl->direction == model::Direction::In) {
    error(ref.loc,
          ref.qualified() + " is an `in` port; " + use +
              " needs a source, which must be an `out` port",
          diag::PortDirection);
  } else if (role_s == "destination" && ref.port_decl->direction == model::Direction::Out) {
    error(ref.loc,
          ref.qualified() + " is an `out` port; " + use +
              " needs a destination, which must be an `in` port",
          diag::PortDirection);
  }
  return true;
}

}  // namespace arbc::frontend
