// Sema of `resource NAME { M.p, ... } [when PRED];`
// (docs/language.md#resource-name--mp-nq---when-predicate): at least two distinct arbitrated `in`
// ports of one type, a unique name, and a bool predicate over the delivered value, bound to
// `emitted`.
#include <set>

#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

// The ports of a resource: each resolves, is arbitrated, is listed once; all share a type,
// which is returned (null if they do not).
TypePtr Sema::check_resource_ports(ResourceDecl& r) {
  std::set<std::string> seen;
  TypePtr type;
  bool same = true;
  size_t unresolved = 0;  // reported at their names; they still count as listed below
  for (PortRef& p : r.ports) {
    if (!resolve_port(p, "destination", "a resource")) {
      ++unresolved;
      continue;
    }
    std::string q = p.qualified();
    if (!seen.insert(q).second) {
      error(p.loc, q + " is listed twice in resource '" + r.name + "'", diag::ResourcePort);
      continue;
    }
    if (!arbitrated_.count(q)) {
      error(p.loc,
            q + " has no `arbitrate` block: a resource is shared by arbitrated ports, whose "
                "rules arbc can check; arbitrate it (or drop it from the resource)",
            diag::ResourcePort);
      continue;
    }
    TypePtr t = p.port_decl->type.resolved;
    if (!t) continue;
    if (!type) {
      type = t;
    } else if (same && !same_type(*type, *t)) {
      same = false;
      error(p.loc,
            "the ports of resource '" + r.name +
                "' must have one type, so that its `when` "
                "means the same on each: " +
                r.ports.front().qualified() + " is " + describe(type) + ", " + q + " is " +
                describe(t),
            diag::ResourceType);
    }
  }
  // A misspelt port is one listed: "lists 1 port" would flag the resource for that typo.
  if (seen.size() + unresolved < 2)
    error(r.loc,
          "resource '" + r.name + "' lists " + std::to_string(seen.size()) + " port" +
              (seen.size() == 1 ? "" : "s") + "; a resource is shared by at least two ports",
          diag::ResourcePort);
  return same ? type : nullptr;
}

// Whether `e` reads the name `name` (a lambda parameter of that name shadows it).
bool mentions_name(const Expr& e, const std::string& name) {
  if (e.kind == Expr::Kind::Name) return e.text == name;
  if (e.kind == Expr::Kind::Lambda && e.text == name) return false;
  for (const ExprPtr& a : e.args)
    if (a && mentions_name(*a, name)) return true;
  return false;
}

// An assert over data: a bool over `emitted`, the value its rule delivers to the port.
void Sema::check_data_assert(AssertDecl& a) {
  if (!a.port.port_decl) return;  // the port did not resolve: reported already
  TypePtr type = a.port.port_decl->type.resolved;
  if (!type) return;
  Scope scope;
  Binding emitted;
  emitted.kind = NameKind::Message;
  emitted.type = type;
  scope.define("emitted", emitted);
  check_condition(*a.property, scope, "an assertion over `emitted`", diag::PredicateType);
}

void Sema::check_resources() {
  std::set<std::string> names;
  for (ResourceDecl& r : spec_.resources) {
    if (!names.insert(r.name).second)
      error(r.loc, "resource '" + r.name + "' is declared twice", diag::Duplicate);
    TypePtr type = check_resource_ports(r);
    if (!r.uses || !type) continue;  // without one type the `when` cannot be typed
    Scope scope;
    Binding emitted;
    emitted.kind = NameKind::Message;
    emitted.type = type;
    scope.define("emitted", emitted);
    check_condition(*r.uses, scope, "the `when` of resource '" + r.name + "'", diag::PredicateType);
  }
}

}  // namespace arbc::frontend
