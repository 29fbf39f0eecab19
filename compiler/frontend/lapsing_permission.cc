#include "compiler/frontend/lapsing_permission.h"

#include "core/check_ids.h"
#include "core/duration_literal.h"
#include "core/join.h"

namespace arbc::frontend {

namespace {

// Does `c` permit something when `event` is present: does the event occur under an even
// number of negations?
bool reads_positively(const Constraint& c, const std::string& event, bool positive = true) {
  switch (c.op) {
    case Constraint::Op::Event:
      return positive && c.event == event;
    case Constraint::Op::Not:
      return reads_positively(c.args[0], event, !positive);
    case Constraint::Op::And:
    case Constraint::Op::Or:
      for (const Constraint& a : c.args)
        if (reads_positively(a, event, positive)) return true;
      return false;
    default:
      return false;
  }
}

// The flag a predicate says is off: `not X` or `X == false` (X a bool field of the message),
// alone or as one side of an `and` (`not engaged and age(stamp) < 100ms`: the flag turning on
// makes the predicate false all the same); null for any other predicate (a threshold, a
// comparison of numbers), whose lapsing is usually what the spec means (`face.certainty >= 0.8
// for 1s` keeps tracking a second).
bool is_flag(const ast::Expr& x) {
  return x.kind == ast::Expr::Kind::Name || x.kind == ast::Expr::Kind::Field;
}

const ast::Expr* flag_said_off(const ast::Expr& p) {
  if (p.kind == ast::Expr::Kind::Unary && p.op == "not" && is_flag(*p.args[0]))
    return p.args[0].get();
  if (p.kind == ast::Expr::Kind::Binary && p.op == "==" && is_flag(*p.args[0]) &&
      p.args[1]->kind == ast::Expr::Kind::Bool && !p.args[1]->boolean)
    return p.args[0].get();
  if (p.kind == ast::Expr::Kind::Binary && p.op == "and") {
    const ast::Expr* left = flag_said_off(*p.args[0]);
    return left ? left : flag_said_off(*p.args[1]);
  }
  return nullptr;
}

std::string flag_text(const ast::Expr& x) {
  if (x.kind == ast::Expr::Kind::Name) return x.text;
  if (x.kind == ast::Expr::Kind::Field) return flag_text(*x.args[0]) + "." + x.text;
  return "the flag";  // under an index (`state.flags[0].on`): said generically
}

Diagnostic lapsing(const ast::DerivedEventDecl& e, const ast::ArbitrateDecl& port,
                   const std::vector<std::string>& rules, const std::string& flag) {
  std::string lifetime = duration_literal(e.lifetime->nanos);
  Diagnostic d;
  d.severity = Severity::Warning;
  d.id = diag::LapsingPermission.text();
  d.loc = e.lifetime->expr->loc;
  d.message = "event '" + e.name + "' stays present for up to " + lifetime + " after a " +
              "message on " + e.source.qualified() + " with " + flag +
              " true (a message on which the predicate is false does not clear an event with "
              "`for`; it lapses), so " +
              (rules.size() == 1 ? "rule '" + rules[0] + "'" : "rules " + join(rules)) + " of " +
              port.port.qualified() + " may deliver for " + lifetime + " after " + flag +
              " turns true";
  std::string who = rules.size() == 1 ? "'" + rules[0] + "'" : "those rules";
  std::string stop = e.name + "_stop";
  add_note(d, "if " + flag + " must stop " + who +
                  " at once, make it a lock (docs/language.md#locks): `event " + stop + " = lock " +
                  e.source.qualified() + " : " + flag + " timeout " + lifetime +
                  ";` and `when not " + stop + "`: a message with " + flag +
                  " false releases it at once, and it stays engaged while the publisher is "
                  "silent for " +
                  lifetime + " or has not spoken since the start");
  return d;
}

}  // namespace

void warn_lapsing_permissions(const ast::Spec& spec, std::vector<Diagnostic>& out) {
  for (const ast::DerivedEventDecl& e : spec.derived_events) {
    if (!e.lifetime || !e.predicate || e.lifetime->nanos.count() <= 0) continue;
    // A delivery event (from an arbitrated `in` port) is set by a delivery, not by a status.
    if (!e.source.port_decl || e.source.port_decl->direction != model::Direction::Out) continue;
    const ast::Expr* flag = flag_said_off(*e.predicate);
    if (!flag) continue;
    for (const ast::ArbitrateDecl& a : spec.arbitrations) {
      std::vector<std::string> rules;
      for (const ast::Rule& r : a.rules)
        if (!r.otherwise && reads_positively(r.constraint, e.name)) rules.push_back(r.name);
      if (!rules.empty()) out.push_back(lapsing(e, a, rules, flag_text(*flag)));
    }
  }
}

}  // namespace arbc::frontend
