#include "compiler/frontend/stray_field.h"

namespace arbc::frontend {

namespace {

std::vector<std::string> not_given(const ast::Expr& literal, const Type& record) {
  std::vector<std::string> out;
  for (const Field& f : record.fields) {
    bool given = false;
    for (const ast::Expr::NameAt& n : literal.names) given |= n.name == f.name;
    if (!given) out.push_back(f.name);
  }
  return out;
}

}  // namespace

std::optional<StrayField> stray_field(const ast::Expr& value, const TypePtr& want) {
  if (!want) return std::nullopt;
  bool local = value.name_kind == ast::NameKind::Let || value.name_kind == ast::NameKind::Var;
  if (value.kind == ast::Expr::Kind::Name && local && value.local && value.local->expr) {
    // Sema checks a `let`'s value before it binds the name, so the chain of names ends.
    auto bound = stray_field(*value.local->expr, want);
    if (bound) bound->via = &value;
    return bound;
  }
  if (value.kind == ast::Expr::Kind::Record && want->kind == Type::Kind::Record) {
    for (size_t i = 0; i < value.names.size() && i < value.args.size(); ++i) {
      const Field* field = want->field(value.names[i].name);
      if (!field) return StrayField{&value.names[i], want, not_given(value, *want)};
      if (value.args[i])
        if (auto inner = stray_field(*value.args[i], field->type)) return inner;
    }
  }
  if (value.kind == ast::Expr::Kind::List && want->kind == Type::Kind::List) {
    for (const ast::ExprPtr& item : value.args)
      if (item)
        if (auto inner = stray_field(*item, want->element)) return inner;
  }
  return std::nullopt;
}

}  // namespace arbc::frontend
