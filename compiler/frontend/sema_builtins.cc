// Semantic analysis of calls: the builtin a call names (core/builtins.h, the one table), its
// arity, and the types of its arguments and result, one case per builtin.
#include "compiler/frontend/builtin_aliases.h"
#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/type_rules.h"

namespace arbc::frontend {

using namespace ast;

// ---- builtins -----------------------------------------------------------------------------

void Sema::check_call(Expr& e, Scope& scope) {
  const BuiltinInfo* info = find_builtin(e.text);  // core/builtins.h, the one table
  const Loc& callee = e.names.empty() ? e.loc : e.names[0].loc;
  if (!info) {
    // The arguments first: `length(v)` of a vec3 means `norm`, of a list `len`.
    for (ExprPtr& arg : e.args)
      if (arg->kind != Expr::Kind::Lambda) check_expr(*arg, scope);
    std::vector<std::string> names;
    for (const BuiltinInfo& b : kBuiltins) names.emplace_back(b.name);
    Diagnostic& d =
        error(callee, "unknown function '" + e.text + "': the builtins are " + builtin_names_text(),
              diag::UnknownFunction);
    if (auto meant = meant_builtin(e.text, names, e.args.empty() ? nullptr : e.args[0]->type))
      did_you_mean(d, *meant);
    return;
  }
  e.builtin = info->id;
  if (!check_arity(e, *info)) return;
  if (info->id == Builtin::MinBy || info->id == Builtin::MaxBy) return check_best_by(e, scope);
  for (ExprPtr& arg : e.args) check_expr(*arg, scope);
  for (ExprPtr& arg : e.args)
    if (!arg->type) return;
  check_builtin_args(e, *info);
}

bool Sema::check_arity(Expr& e, const BuiltinInfo& info) {
  int n = static_cast<int>(e.args.size());
  if (n >= info.min_args && (info.max_args < 0 || n <= info.max_args)) return true;
  error(e.loc,
        "'" + e.text + "' takes " +
            (info.max_args < 0 ? "at least " + std::to_string(info.min_args)
                               : std::to_string(info.min_args)) +
            (info.min_args == 1 && info.max_args == 1 ? " argument" : " arguments") + ", not " +
            std::to_string(n) + ": " + std::string(info.signature),
        diag::Arity);
  return false;
}

void Sema::check_best_by(Expr& e, Scope& scope) {
  Expr& list = *e.args[0];
  Expr& key = *e.args[1];
  check_expr(list, scope);
  if (key.kind != Expr::Kind::Lambda) {
    check_expr(key, scope);
    error(key.loc, "the second argument of '" + e.text + "' is a function such as o => o.dist",
          diag::TypeMismatch);
    return;
  }
  if (!list.type) return;
  if (list.type->kind != Type::Kind::List || !list.type->element) {
    error(list.loc, "'" + e.text + "' needs a list, not " + describe(list.type),
          diag::TypeMismatch);
    return;
  }
  scope.push();
  Binding param;
  param.kind = NameKind::Param;
  param.type = list.type->element;
  param.lambda = &key;
  scope.define(key.text, param);
  check_expr(*key.args[0], scope);
  scope.pop();
  if (!check_uint64_operand(*key.args[0], "the key of '" + e.text + "'")) return;
  if (key.args[0]->type && !is_numeric(key.args[0]->type)) {
    error(key.args[0]->loc,
          "the key of '" + e.text + "' must be a number, not " + describe(key.args[0]->type),
          diag::TypeMismatch);
    return;
  }
  e.type = list.type->element;
}

void Sema::check_builtin_args(Expr& e, const BuiltinInfo& info) {
  auto expect = [&](size_t i, bool ok, const char* what) {
    if (!ok)
      error(e.args[i]->loc,
            "argument " + std::to_string(i + 1) + " of '" + e.text + "' must be " + what +
                ", not " + describe(e.args[i]->type) + " (" + std::string(info.signature) + ")",
            diag::TypeMismatch);
    return ok;
  };
  for (const ExprPtr& arg : e.args)
    if (!check_uint64_operand(*arg, "'" + e.text + "'")) return;
  switch (info.id) {
    case Builtin::Len: {
      const TypePtr& t = e.args[0]->type;
      if (expect(0, is_kind(t, Type::Kind::List) || is_kind(t, Type::Kind::String),
                 "a list or a string"))
        e.type = kInt;
      return;
    }
    case Builtin::Dist:
      if (expect(0, is_kind(e.args[0]->type, Type::Kind::Vec3), "a vec3") &&
          expect(1, is_kind(e.args[1]->type, Type::Kind::Vec3), "a vec3"))
        e.type = kFloat;
      return;
    case Builtin::Norm:
      if (expect(0, is_kind(e.args[0]->type, Type::Kind::Vec3), "a vec3")) e.type = kFloat;
      return;
    case Builtin::Abs:
      if (expect(0, is_numeric(e.args[0]->type), "a number")) {
        e.type = promoted(e.args[0]->type);
        e.is_duration = e.args[0]->is_duration;
      }
      return;
    case Builtin::Min:
    case Builtin::Max: {
      TypePtr t = kInt;
      bool durations = true;
      for (size_t i = 0; i < e.args.size(); ++i) {
        if (!expect(i, is_numeric(e.args[i]->type), "a number")) return;
        t = numeric_join(t, e.args[i]->type);
        durations = durations && e.args[i]->is_duration;
      }
      e.type = t;
      e.is_duration = durations;
      return;
    }
    case Builtin::Now:
      e.type = kFloat;
      return;
    case Builtin::Age:  // a stamp: builtin_interfaces/msg/Time, or any record of the same fields
      if (expect(0, is_stamp(e.args[0]->type),
                 "a stamp, a record with integer fields sec and "
                 "nanosec (a Header's `stamp`)")) {
        e.type = kFloat;
        e.is_duration = true;
      }
      return;
    case Builtin::Vec3:
      for (size_t i = 0; i < 3; ++i)
        if (!expect(i, is_numeric(e.args[i]->type), "a number")) return;
      e.type = kVec3;
      return;
    default:
      return;
  }
}

}  // namespace arbc::frontend
