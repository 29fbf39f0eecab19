#include "compiler/frontend/field_mismatch.h"

#include "compiler/frontend/value_fit.h"

namespace arbc::frontend {

std::optional<FieldMismatch> field_mismatch(const ast::Expr& value, const TypePtr& want) {
  if (!want) return std::nullopt;
  if (value.kind == ast::Expr::Kind::Record && want->kind == Type::Kind::Record) {
    for (size_t i = 0; i < value.names.size() && i < value.args.size(); ++i) {
      const Field* field = want->field(value.names[i].name);
      const ast::Expr* arg = value.args[i].get();
      if (!field || !arg || !arg->type || !field->type) continue;
      if (value_fits(*arg, field->type)) continue;
      if (auto inner = field_mismatch(*arg, field->type)) return inner;  // deeper is plainer
      return FieldMismatch{field->name, arg, &value, field->type};
    }
    for (const Field& f : want->fields) {
      bool given = false;
      for (const ast::Expr::NameAt& n : value.names) given |= n.name == f.name;
      if (!given) return FieldMismatch{f.name, nullptr, &value, f.type};
    }
  }
  if (value.kind == ast::Expr::Kind::List && want->kind == Type::Kind::List) {
    for (const ast::ExprPtr& item : value.args)
      if (item && item->type && want->element && !value_fits(*item, want->element))
        if (auto inner = field_mismatch(*item, want->element)) return inner;
  }
  return std::nullopt;
}

}  // namespace arbc::frontend
