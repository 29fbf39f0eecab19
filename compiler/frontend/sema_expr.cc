// Semantic analysis of expressions: name resolution, types, constants and constraints
// (durations: sema_duration.cc; calls of builtins: sema_builtins.cc). Every checked Expr records
// its type and what its names refer to (ast.h).
#include <cmath>
#include <cstdio>
#include <limits>

#include "compiler/frontend/builtin_aliases.h"
#include "compiler/frontend/ros2_constants.h"
#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/type_rules.h"
#include "core/join.h"

namespace arbc::frontend {

using namespace ast;

namespace {

const char* const kIntTooBig =
    "this int does not fit in 64 bits (-9223372036854775808 to 9223372036854775807): write it "
    "as a float (with a decimal point) or use a smaller value";

const char* kind_word(Expr::Kind kind) {
  switch (kind) {
    case Expr::Kind::Number:
      return "a number";
    case Expr::Kind::Duration:
      return "a duration";
    case Expr::Kind::String:
      return "a string";
    case Expr::Kind::Field:
      return "a field access";
    case Expr::Kind::Index:
      return "an index";
    case Expr::Kind::Record:
      return "a record";
    case Expr::Kind::List:
      return "a list";
    case Expr::Kind::Lambda:
      return "a lambda";
    case Expr::Kind::Call:
      return "a function call";
    default:
      return "an arithmetic or comparison operator";
  }
}

}  // namespace

// ---- expressions, one function per kind --------------------------------------------------

void Sema::check_expr(Expr& e, Scope& scope) {
  switch (e.kind) {
    case Expr::Kind::Number:
      if (e.is_int && e.int_too_big && uint64_literal(e)) return;
      if (e.is_int && e.int_too_big) {
        error(e.loc, kIntTooBig, diag::IntOverflow);
        return;
      }
      e.type = e.is_int ? kInt : kFloat;
      return;
    case Expr::Kind::Duration:
      e.type = kFloat;
      e.is_duration = true;
      return;
    case Expr::Kind::String:
      e.type = kString;
      return;
    case Expr::Kind::Bool:
      e.type = kBool;
      return;
    case Expr::Kind::Otherwise:
      error(e.loc, "'otherwise' is a whole rule constraint (`when otherwise`), not a value",
            diag::Otherwise);
      return;
    case Expr::Kind::Name:
      return check_name(e, scope);
    case Expr::Kind::Field:
      return check_field(e, scope);
    case Expr::Kind::Index:
      return check_index(e, scope);
    case Expr::Kind::Unary:
      return check_unary(e, scope);
    case Expr::Kind::Binary:
      return check_binary(e, scope);
    case Expr::Kind::Record:
      return check_record(e, scope);
    case Expr::Kind::List:
      return check_list(e, scope);
    case Expr::Kind::Lambda:
      error(e.loc, "a lambda ('x => ...') can only be the second argument of min_by or max_by",
            diag::Lambda);
      return;
    case Expr::Kind::Call:
      check_call(e, scope);
      return;
  }
}

// A name: a local, the message or a lambda parameter (innermost first), then a constant;
// an event or an unknown name is reported.
void Sema::check_name(Expr& e, Scope& scope) {
  if (const Binding* b = scope.find(e.text)) {
    if (b->message_unavailable) {
      error(e.loc,
            "the message '" + e.text +
                "' is not available in an `every` body: it runs on a timer, not on a message",
            diag::StatementContext);
      return;
    }
    e.name_kind = b->kind;
    e.type = b->type;
    e.is_duration = b->is_duration;
    e.local = b->local;
    e.lambda = b->lambda;
    return;
  }
  auto k = consts_.find(e.text);
  if (k != consts_.end()) {
    check_const(k->second);
    ConstDecl& c = spec_.consts[k->second];
    e.name_kind = NameKind::Const;
    e.constant = &c;
    if (c.value) {
      e.type = c.value->type;
      e.is_duration = c.value->is_duration;
    }
    return;
  }
  if (e.text == "nan" || e.text == "inf") {
    // The floats without a decimal form, as counterexamples print them (docs/language.md).
    e.kind = Expr::Kind::Number;
    e.number = e.text == "nan" ? std::numeric_limits<double>::quiet_NaN()
                               : std::numeric_limits<double>::infinity();
    e.is_int = false;
    e.type = kFloat;
    return;
  }
  if (events_.count(e.text)) {
    error(e.loc,
          "event '" + e.text +
              "' cannot be read in a value expression: events appear in `when`, `assert` "
              "and `invariant` constraints",
          diag::EventInExpression);
    return;
  }
  std::vector<std::string> candidates = scope.names();
  for (auto& [name, index] : consts_) candidates.push_back(name);
  Diagnostic& d =
      unknown(e.loc, "unknown name '" + e.text + "'", diag::UnknownName, e.text, candidates);
  // `accept Joy.cmd.vx < 2` reads like a port reference, but a body names the message alone.
  std::string message = scope.message_name();
  if (modules_.count(e.text) && !message.empty()) {
    Diagnostic note;
    note.severity = Severity::Note;
    note.message = "'" + e.text +
                   "' is a module: in this body the incoming message is named after its source "
                   "port, '" +
                   message + "' (write " + message + ".x, not " + e.text + "." + message + ".x)";
    d.notes.push_back(std::move(note));
  } else if (d.notes.empty()) {  // no close name: what a name can be here
    Diagnostic note;
    note.severity = Severity::Note;
    note.message = std::string("a name is ") +
                   (message.empty() ? "" : "the incoming message, '" + message + "', ") +
                   "a `let` or `var` written before it, or a `const`";
    d.notes.push_back(std::move(note));
  }
}

namespace {

// The field's name alone in `base.field` (the expression's last token; names are ASCII): what
// an unknown field points at, so that an editor's "did you mean" fix replaces the name only.
Loc field_name_loc(const Expr& e) {
  Loc at = e.loc;
  int length = static_cast<int>(e.text.size());
  if (at.end_line <= 0 || at.end_column - length < 1) return at;
  at.line = at.end_line;
  at.column = at.end_column - length;
  return at;
}

// `xs.length`, `s.size`, `v.length`: the language has no methods, and a length is a builtin
// function. A note saying which one, for a name that means a length (builtin_aliases.h); not
// "did you mean", whose quick fix would put the function's name in place of the field's.
void note_length_function(Diagnostic& d, const Expr& e, const TypePtr& base) {
  if (!is_kind(base, Type::Kind::List) && !is_kind(base, Type::Kind::String) &&
      !is_kind(base, Type::Kind::Vec3))
    return;
  std::optional<std::string> meant =
      e.text == "len" || e.text == "norm" ? e.text : meant_builtin(e.text, {"len", "norm"}, base);
  bool vec3 = base->kind == Type::Kind::Vec3;
  if (!meant || *meant != (vec3 ? "norm" : "len")) return;
  Diagnostic note;
  note.severity = Severity::Note;
  note.message = std::string(vec3                             ? "a vec3's length"
                             : base->kind == Type::Kind::List ? "a list's length"
                                                              : "a string's length") +
                 " is the builtin function " + *meant + "(...), not a field";
  d.notes.push_back(std::move(note));
}

}  // namespace

// `base.field` of a record or a vec3.
void Sema::check_field(Expr& e, Scope& scope) {
  Expr& base = *e.args[0];
  // `Range.ULTRASOUND`: a constant of a message `use ros2` declared (ros2_constants.h), when
  // `Range` names no value here.
  if (base.kind == Expr::Kind::Name && !scope.find(base.text) && !consts_.count(base.text) &&
      consts_.count(msg_constant_name(base.text, e.text))) {
    e.kind = Expr::Kind::Name;
    e.text = msg_constant_name(base.text, e.text);
    e.args.clear();
    check_name(e, scope);
    return;
  }
  check_expr(base, scope);
  if (!base.type) return;
  if (base.type->kind == Type::Kind::Vec3) {
    if (e.text == "x" || e.text == "y" || e.text == "z") {
      e.type = kFloat;
      return;
    }
    Diagnostic& d =
        unknown(field_name_loc(e), "vec3 has no field '" + e.text + "' (it has x, y and z)",
                diag::UnknownField, e.text, {"x", "y", "z"});
    note_length_function(d, e, base.type);
    return;
  }
  if (base.type->kind != Type::Kind::Record) {
    Diagnostic& d = error(
        e.loc, "'." + e.text + "' needs a record or a vec3, but this is " + describe(base.type),
        diag::TypeMismatch);
    note_length_function(d, e, base.type);
    return;
  }
  std::vector<std::string> names;
  for (const Field& f : base.type->fields) {
    if (f.name == e.text) {
      e.type = f.type;
      return;
    }
    names.push_back(f.name);
  }
  // The fields it has, as for a vec3, so that a name too far for "did you mean" (`distance`
  // for `dist`) still shows what to write; a long record's list would drown the line.
  std::string has;
  if (!names.empty() && names.size() <= 8) has = " (it has " + join(names, ", ", " and ") + ")";
  unknown(field_name_loc(e), describe(base.type) + " has no field '" + e.text + "'" + has,
          diag::UnknownField, e.text, names);
}

// `list[int]`: the list's element type.
void Sema::check_index(Expr& e, Scope& scope) {
  check_expr(*e.args[0], scope);
  check_expr(*e.args[1], scope);
  const TypePtr& list = e.args[0]->type;
  const TypePtr& index = e.args[1]->type;
  if (list && list->kind != Type::Kind::List) {
    error(e.loc, "only lists can be indexed, but this is " + describe(list), diag::TypeMismatch);
    return;
  }
  if (index && index->kind != Type::Kind::Int) {
    error(e.args[1]->loc, "a list index must be an int, not " + describe(index),
          diag::TypeMismatch);
    return;
  }
  if (list) e.type = list->element;
}

// `not bool`, or `-` of a number or a vec3 (a negated duration stays one).
void Sema::check_unary(Expr& e, Scope& scope) {
  Expr& operand = *e.args[0];
  check_expr(operand, scope);
  if (!operand.type) return;
  if (e.op == "not") {
    if (operand.type->kind != Type::Kind::Bool) {
      error(e.loc, "'not' needs a bool, not " + describe(operand.type), diag::TypeMismatch);
      return;
    }
    e.type = kBool;
    fold_operator(e);
    return;
  }
  if (!is_numeric(operand.type) && operand.type->kind != Type::Kind::Vec3) {
    error(e.loc, "unary '-' needs a number or a vec3, not " + describe(operand.type),
          diag::TypeMismatch);
    return;
  }
  // `-9223372036854775809`: its digits are a uint64 literal, but no int is that negative.
  if (operand.kind == Expr::Kind::Number && operand.int_too_big) {
    error(operand.loc, kIntTooBig, diag::IntOverflow);
    return;
  }
  if (!check_uint64_operand(operand, "unary '-'")) return;
  e.type = promoted(operand.type);
  e.is_duration = operand.is_duration;
  fold_operator(e);
}

// The type of `a op b` by the operand types; durations stay durations where the units do.
void Sema::check_binary(Expr& e, Scope& scope) {
  Expr& a = *e.args[0];
  Expr& b = *e.args[1];
  check_expr(a, scope);
  check_expr(b, scope);
  if (!a.type || !b.type) return;
  auto mismatch = [&] {
    error(e.loc,
          "operator '" + std::string(e.op) + "' cannot combine " + describe(a.type) + " and " +
              describe(b.type),
          diag::TypeMismatch);
  };
  std::string_view op = e.op;
  if (!check_uint64_binary(e)) return;
  if (op == "and" || op == "or") {
    if (a.type->kind != Type::Kind::Bool || b.type->kind != Type::Kind::Bool) return mismatch();
    e.type = kBool;
  } else if (op == "==" || op == "!=") {
    bool ok = (is_numeric(a.type) && is_numeric(b.type)) ||
              (assignable(*a.type, *b.type, false) && assignable(*b.type, *a.type, false));
    if (!ok) return mismatch();
    e.type = kBool;
  } else if (op == "<" || op == "<=" || op == ">" || op == ">=") {
    bool ok = (is_numeric(a.type) && is_numeric(b.type)) ||
              (is_kind(a.type, Type::Kind::String) && is_kind(b.type, Type::Kind::String));
    if (!ok) return mismatch();
    e.type = kBool;
  } else if (is_numeric(a.type) && is_numeric(b.type)) {
    e.type = op == "/" ? kFloat : numeric_join(a.type, b.type);
    if (op == "+" || op == "-") e.is_duration = a.is_duration && b.is_duration;
    if (op == "*") e.is_duration = a.is_duration != b.is_duration;
    if (op == "/") e.is_duration = a.is_duration && !b.is_duration;
  } else if (is_kind(a.type, Type::Kind::Vec3) && is_kind(b.type, Type::Kind::Vec3) &&
             (op == "+" || op == "-")) {
    e.type = kVec3;
  } else if (is_kind(a.type, Type::Kind::Vec3) && is_numeric(b.type) && (op == "*" || op == "/")) {
    e.type = kVec3;
  } else if (is_numeric(a.type) && is_kind(b.type, Type::Kind::Vec3) && op == "*") {
    e.type = kVec3;
  } else if (is_kind(a.type, Type::Kind::String) && is_kind(b.type, Type::Kind::String) &&
             op == "+") {
    e.type = kString;
  } else {
    mismatch();
  }
  fold_operator(e);
}

// `{ name: value, ... }`: a record type of its fields, each named once.
void Sema::check_record(Expr& e, Scope& scope) {
  std::vector<Field> fields;
  bool ok = true;
  for (size_t i = 0; i < e.args.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (e.names[j].name == e.names[i].name) {
        error(e.names[i].loc, "field '" + e.names[i].name + "' is given twice", diag::Duplicate);
      }
    }
    check_expr(*e.args[i], scope);
    if (!e.args[i]->type) ok = false;
    fields.push_back({e.names[i].name, e.args[i]->type});
  }
  if (ok) e.type = Type::record(std::move(fields));
}

// `[ items ]`: one element type (ints and floats together are floats).
void Sema::check_list(Expr& e, Scope& scope) {
  TypePtr element;
  bool ok = true;
  for (ExprPtr& item : e.args) {
    check_expr(*item, scope);
    if (!item->type) {
      ok = false;
      continue;
    }
    if (!element) {
      element = item->type;
    } else if (is_numeric(element) && is_numeric(item->type)) {
      if (!check_uint64_list_item(*item, element)) {
        ok = false;
        continue;
      }
      element = numeric_join(element, item->type);
    } else if (assignable(*item->type, *element)) {
      continue;
    } else if (TypePtr joined = item_join(element, item->type)) {
      element = joined;  // [{x: 0}, {x: 0.5}]: the items' records together
    } else {
      error(item->loc,
            "list items must have one type: this is " + describe(item->type) +
                ", earlier items are " + describe(element),
            diag::TypeMismatch);
      ok = false;
    }
  }
  if (ok) e.type = Type::list(element);
}

void Sema::check_condition(Expr& e, Scope& scope, const std::string& what, DiagId id) {
  check_expr(e, scope);
  if (e.type && e.type->kind != Type::Kind::Bool)
    error(e.loc, what + " must be a bool, not " + describe(e.type), id);
}

// ---- constants (durations: sema_duration.cc) -------------------------------------------------

// ---- constraints --------------------------------------------------------------------------

Constraint Sema::check_constraint(Expr& e, const std::string& where, bool otherwise_ok) {
  switch (e.kind) {
    case Expr::Kind::Bool:
      e.type = kBool;
      return Constraint::constant(e.boolean);
    case Expr::Kind::Otherwise:
      if (!otherwise_ok)
        error(e.loc,
              "'otherwise' must be a rule's whole constraint (`when otherwise`), not part of " +
                  where,
              diag::Otherwise);
      return Constraint::constant(false);
    case Expr::Kind::Name: {
      if (events_.count(e.text)) {
        e.name_kind = NameKind::Event;
        e.type = kBool;
        return Constraint::event_ref(e.text);
      }
      if (consts_.count(e.text)) {
        error(e.loc,
              "'" + e.text + "' is a constant; " + where +
                  " may mention only events, true, false, not, and, or",
              diag::ConstraintTerm);
        return Constraint::constant(false);
      }
      unknown_event(e.loc, e.text, false);
      return Constraint::constant(false);
    }
    case Expr::Kind::Unary:
      if (e.op == "not") {
        e.type = kBool;
        return Constraint::negate(check_constraint(*e.args[0], where, false));
      }
      break;
    case Expr::Kind::Binary:
      if (e.op == "and" || e.op == "or") {
        e.type = kBool;
        std::vector<Constraint> parts;
        parts.reserve(2);
        parts.push_back(check_constraint(*e.args[0], where, false));
        parts.push_back(check_constraint(*e.args[1], where, false));
        return e.op == "and" ? Constraint::conjunction(std::move(parts))
                             : Constraint::disjunction(std::move(parts));
      }
      break;
    default:
      break;
  }
  error(e.loc,
        std::string(kind_word(e.kind)) + " cannot appear in " + where +
            ": it may mention only events, true, false, not, and, or (compute a derived event "
            "with `event NAME = Module.port : PREDICATE;`)",
        diag::ConstraintTerm);
  return Constraint::constant(false);
}

}  // namespace arbc::frontend
