#include "compiler/frontend/ros2_uses.h"

#include <map>
#include <set>
#include <string>

#include "compiler/frontend/frontend.h"
#include "compiler/frontend/ros2_constants.h"
#include "core/check_ids.h"
#include "core/join.h"
#include "core/ros2_known_messages.h"
#include "core/ros2_msg_path.h"

namespace arbc::frontend {

using namespace ast;

namespace {

Diagnostic& add_error(std::vector<Diagnostic>& out, const Loc& loc, std::string message) {
  Diagnostic d;
  d.loc = loc;
  d.message = std::move(message);
  d.id = diag::Ros2Message.text();
  out.push_back(std::move(d));
  return out.back();
}

// A note at a line of a .msg file (a built-in definition has no file: no note).
void note_at_file(Diagnostic& d, const std::string& file, int line, int column,
                  std::string message) {
  if (file.empty()) return;
  Diagnostic note;
  note.severity = Severity::Note;
  note.loc.file = file;
  note.loc.line = line;
  note.loc.column = column;
  note.message = std::move(message);
  d.notes.push_back(std::move(note));
}

// Where definitions were looked for, and how to add a folder: the end of a "not found" error.
std::string where_looked(const std::vector<std::string>& path, const std::string& package) {
  std::string how = "give the folder that holds " + package +
                    "/msg/ with --msg-path DIR or ARBC_MSG_PATH, or source a ROS 2 setup file "
                    "(AMENT_PREFIX_PATH)";
  if (path.empty()) return "the message path is empty: " + how;
  std::vector<std::string> quoted;
  for (const std::string& dir : path) quoted.push_back("'" + dir + "'");
  return "looked in " + join(quoted, ", ", " and ") + ": " + how;
}

class Declarer {
 public:
  Declarer(Spec& spec, std::vector<Diagnostic>& out, const std::vector<std::string>& first)
      : spec_(spec),
        out_(out),
        failed_(spec.failed_uses),
        library_(ros2::message_path(first), ros2::known_message_texts()) {
    for (const TypeDecl& t : spec_.types) taken_.insert(t.name);
  }

  void run() {
    // Pass 1: each message a `use` names keeps its own name, whatever uses it first.
    std::vector<std::pair<const UseDecl*, const ros2::MsgDefinition*>> used;
    for (const UseDecl& u : spec_.uses) {
      const ros2::MsgDefinition* def = find_used(u);
      if (!def) {
        failed_.insert(u.name);
        continue;
      }
      auto [it, fresh] = names_.emplace(def->full_name(), def->name);
      if (!fresh) continue;  // the same message used twice: declared once
      taken_.insert(def->name);
      used.push_back({&u, def});
      uses_[def->full_name()] = &u;
    }
    // Pass 2: declare them, each message they use first.
    for (const auto& [use, def] : used) declare(*def, *use);
  }

 private:
  // The definition a `use` names; null (reported) when there is none.
  const ros2::MsgDefinition* find_used(const UseDecl& u) {
    if (u.system != "ros2") {
      add_error(out_, u.system_loc,
                "`use " + u.system +
                    "`: arbc reads ROS 2 message definitions only; write `use "
                    "ros2 PKG/msg/NAME;`");
      return nullptr;
    }
    size_t first = u.written.find('/'), last = u.written.rfind('/');
    if (first != last && u.written.substr(first + 1, last - first - 1) != "msg") {
      add_error(out_, u.loc,
                "'" + u.written +
                    "' is not a message: only messages (PKG/msg/NAME) are types "
                    "of ports; services and actions are not");
      return nullptr;
    }
    std::string full = u.package + "/msg/" + u.name;
    ros2::MsgError err;
    const ros2::MsgDefinition* def = library_.find(full, &err);
    if (def) return def;

    if (err.message.empty()) {
      add_error(out_, u.loc,
                "no definition of " + full + " on the message path; " +
                    where_looked(library_.path(), u.package));
    } else {
      std::string place =
          err.file.empty() ? "arbc's built-in " + full : err.file + ":" + std::to_string(err.line);
      Diagnostic& d =
          add_error(out_, u.loc, full + " cannot be read (" + place + "): " + err.message);
      note_at_file(d, err.file, err.line, err.column, "here");
    }
    return nullptr;
  }

  // Declares `def` (and, first, each message it uses) as a record type; the name it got. Its
  // place is its own `use`, else that of the used message that needs it (`by`).
  std::string declare(const ros2::MsgDefinition& def, const UseDecl& by) {
    std::string full = def.full_name();
    const UseDecl& use = uses_.count(full) ? *uses_.at(full) : by;
    if (declared_.count(full)) return names_.at(full);
    declared_.insert(full);
    std::string name = names_.count(full) ? names_.at(full) : own_name(def);
    names_[full] = name;
    TypeDecl t;
    t.name = name;
    t.loc = use.name_loc;
    t.ros2 = full;
    t.msg_file = def.file;
    t.type.kind = TypeExpr::Kind::Record;
    t.type.loc = use.loc;
    bool ok = true;
    for (const ros2::MsgField& f : def.fields) {
      std::unique_ptr<TypeExpr> field = field_type(def, f, use);
      if (!field) {
        ok = false;
        continue;
      }
      t.type.fields.emplace_back(f.name, std::move(field));
      t.type.field_locs.push_back(use.loc);
    }
    if (ok) spec_.types.push_back(std::move(t));
    if (!ok) failed_.insert(name);
    if (ok) declare_constants(def, name, use);
    return name;
  }

  // `uint8 ULTRASOUND=0` of Range as the constant `Range.ULTRASOUND` (ros2_constants.h).
  void declare_constants(const ros2::MsgDefinition& def, const std::string& type_name,
                         const UseDecl& use) {
    for (const ros2::MsgConstant& c : def.constants) {
      std::string why;
      std::optional<ExprPtr> value = msg_constant_literal(c, use.loc, &why);
      if (!value) {
        std::string where = def.file.empty() ? "arbc's built-in " + def.full_name()
                                             : def.file + ":" + std::to_string(c.line);
        Diagnostic& d = add_error(out_, use.loc,
                                  def.full_name() + ": constant '" + c.name + "' (" + where +
                                      ") cannot be read: " + why + "; fix its definition");
        note_at_file(d, def.file, c.line, c.column, "constant '" + c.name + "' is here");
        continue;
      }
      ConstDecl k;
      k.name = msg_constant_name(type_name, c.name);
      k.value = std::move(*value);
      k.loc = use.name_loc;
      spec_.consts.push_back(std::move(k));
    }
  }

  // A message a used one uses: its name unless the spec has that name, then PKG_NAME (then
  // PKG_NAME_2, ...): a name a spec could write, as app.json's names are.
  std::string own_name(const ros2::MsgDefinition& def) {
    std::string name = def.name;
    for (int n = 1; taken_.count(name); ++n)
      name = def.package + "_" + def.name + (n > 1 ? "_" + std::to_string(n) : "");
    taken_.insert(name);
    return name;
  }

  std::unique_ptr<TypeExpr> field_type(const ros2::MsgDefinition& def, const ros2::MsgField& f,
                                       const UseDecl& use) {
    auto refuse = [&](const std::string& why) {
      std::string where = def.file.empty() ? "arbc's built-in " + def.full_name()
                                           : def.file + ":" + std::to_string(f.line);
      Diagnostic& d = add_error(
          out_, use.loc, def.full_name() + ": field '" + f.name + "' (" + where + ") " + why);
      note_at_file(d, def.file, f.line, f.column, "field '" + f.name + "' is here");
      return nullptr;
    };
    auto element = std::make_unique<TypeExpr>();
    element->loc = use.loc;
    if (!f.type.primitive) {
      ros2::MsgError loaded;  // find() loaded every message `def` uses already: no error here
      const ros2::MsgDefinition* inner = library_.find(f.type.name, &loaded);
      if (!inner) return refuse("is a " + f.type.name + ", which could not be read");
      element->kind = TypeExpr::Kind::Named;
      element->name = declare(*inner, use);
      if (!declared_ok(inner->full_name())) return nullptr;
    } else if (f.type.name == "bool") {
      element->kind = TypeExpr::Kind::Bool;
    } else if (f.type.name == "string") {
      element->kind = TypeExpr::Kind::String;
      if (f.type.string_bound <= Type::kMaxSize) element->size = f.type.string_bound;
    } else if (f.type.name == "wstring") {
      return refuse("is a wstring, which arbc does not hold: use string");
    } else {
      element->kind = TypeExpr::Kind::Named;  // a number type: resolved by its .msg spelling
      element->name = f.type.name;
    }
    if (f.type.array == ros2::MsgType::Array::None) return element;
    auto list = std::make_unique<TypeExpr>();
    list->kind = TypeExpr::Kind::List;
    list->loc = use.loc;
    list->element = std::move(element);
    // T[N] holds exactly N, T[<=N] at most N; a bound above Type::kMaxSize is refused by sema.
    list->fixed = f.type.array == ros2::MsgType::Array::Fixed;
    if (list->fixed && f.type.array_size > Type::kMaxSize)
      return refuse("is a fixed-size array of " + std::to_string(f.type.array_size) +
                    " elements; arbc holds T[N] up to N = " + std::to_string(Type::kMaxSize));
    // A bound above that is dropped: at most N is then unchecked, which every proof allows.
    if (f.type.array != ros2::MsgType::Array::Sequence && f.type.array_size <= Type::kMaxSize)
      list->size = f.type.array_size;
    return list;
  }

  // Whether the message's declaration was made (a field it could not hold drops it, reported).
  bool declared_ok(const std::string& full) const {
    for (const TypeDecl& t : spec_.types)
      if (t.ros2 == full) return true;
    return false;
  }

  Spec& spec_;
  std::vector<Diagnostic>& out_;
  std::set<std::string>& failed_;  // spec_.failed_uses
  ros2::MsgLibrary library_;
  std::set<std::string> taken_;                 // type names already given
  std::map<std::string, std::string> names_;    // "pkg/msg/Name" -> its type's name
  std::set<std::string> declared_;              // full names declare() has started
  std::map<std::string, const UseDecl*> uses_;  // "pkg/msg/Name" -> the `use` naming it
};

// A type as a spec writes it: `{ linear: Vector3, angular: Vector3 }`.
std::string type_text(const ast::TypeExpr& t) {
  switch (t.kind) {
    case ast::TypeExpr::Kind::Bool:
      return "bool";
    case ast::TypeExpr::Kind::String:
      return t.size > 0 ? "string<" + std::to_string(t.size) + ">" : "string";
    case ast::TypeExpr::Kind::List:
      if (t.fixed) return type_text(*t.element) + "[" + std::to_string(t.size) + "]";
      if (t.size > 0) return "list<" + type_text(*t.element) + ", " + std::to_string(t.size) + ">";
      return "list<" + type_text(*t.element) + ">";
    case ast::TypeExpr::Kind::Record: {
      std::string out = "{ ";
      for (size_t i = 0; i < t.fields.size(); ++i)
        out += (i ? ", " : "") + t.fields[i].first + ": " + type_text(*t.fields[i].second);
      return out + " }";
    }
    case ast::TypeExpr::Kind::Named:
      return t.name;
    case ast::TypeExpr::Kind::Int:
      return "int";
    case ast::TypeExpr::Kind::Float:
      return "float";
    case ast::TypeExpr::Kind::Vec3:
      return "vec3";
  }
  return "";
}

}  // namespace

void declare_ros2_uses(Spec& spec, std::vector<Diagnostic>& out,
                       const std::vector<std::string>& first) {
  if (spec.uses.empty()) return;
  Declarer(spec, out, first).run();
}

std::string ros2_types_text(const std::vector<std::string>& messages,
                            const std::vector<std::string>& first, const std::string& file,
                            std::vector<Diagnostic>* diagnostics) {
  Spec spec;
  spec.file = file;
  for (const std::string& full : messages) {
    UseDecl u;
    u.system = "ros2";
    u.written = full;
    u.package = full.substr(0, full.find('/'));
    u.name = full.substr(full.rfind('/') + 1);
    u.loc.file = file;
    spec.uses.push_back(u);
  }
  declare_ros2_uses(spec, *diagnostics, first);
  std::string out;
  for (const TypeDecl& t : spec.types)
    out += "\n// " + t.ros2 + "\ntype " + t.name + " = " + type_text(t.type) + ";\n";
  return out;
}

}  // namespace arbc::frontend
