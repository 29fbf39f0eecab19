// Semantic checks of properties over time (docs/language.md#properties-over-time): the rules a
// property names exist and are unambiguous, a window is a positive duration, an absence's event
// is an event of the rule's port, and a precedence, a response and a spacing after another rule
// relate two rules of one port.
#include <string>
#include <vector>

#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

namespace {

const char* shape_name(TemporalDecl::Kind k) {
  if (k == TemporalDecl::Kind::Response) return "an `after ... within` property";
  return k == TemporalDecl::Kind::Precedence ? "an `only ... after` property"
                                             : "a `never` property";
}

// What to do when a property over two rules names one rule twice.
std::string same_rule_fix(const TemporalDecl& n) {
  switch (n.kind) {
    case TemporalDecl::Kind::Response:
      return "`after " + n.other + ", " + n.rule +
             " within ...` names one rule twice: name the rule that must respond";
    case TemporalDecl::Kind::Spacing:
      return "`never " + n.rule + " within ... after " + n.other +
             "` names one rule twice: a rule spaced from itself reads `never two " + n.rule +
             " within ...;`";
    default:
      return "`only " + n.rule + " after " + n.other +
             "` names one rule twice: name the rule that must deliver first";
  }
}

const char* pair_shape(TemporalDecl::Kind k) {
  if (k == TemporalDecl::Kind::Response) return "`after ..., ... within`";
  return k == TemporalDecl::Kind::Spacing ? "`never ... within ... after`" : "`only ... after`";
}

}  // namespace

const Rule* Sema::unique_rule(const std::string& name, const Loc& loc, const std::string& what) {
  std::vector<const Rule*> found;
  std::vector<std::string> all;
  for (const ArbitrateDecl& a : spec_.arbitrations) {
    for (const Rule& r : a.rules) {
      all.push_back(r.name);
      if (r.name == name) found.push_back(&r);
    }
  }
  if (found.empty()) {
    unknown(loc, "no rule is named '" + name + "'", diag::UnknownRule, name, all);
    return nullptr;
  }
  if (found.size() > 1) {
    // Rule names are per port; a property over time must say which rule it is about.
    error(loc,
          "rule name '" + name + "' is used by " + std::to_string(found.size()) + " ports; " +
              what + " can name only a rule whose name is unique: rename one",
          diag::TemporalRule);
    return nullptr;
  }
  return found.front();
}

std::vector<std::string> Sema::activity_events(const ArbitrateDecl& port) const {
  std::vector<std::string> out;
  if (!port.by_priority) return out;
  for (const Rule& r : port.rules)
    if (r.hold) out.push_back(activity_event_name(r.name));
  return out;
}

// `never RULE while EVENT;`: EVENT is a declared event or the activity event `act_<R>` of a
// `by priority` rule R of RULE's port (a rule with a hold), the events of that port's container.
void Sema::check_absence_event(TemporalDecl& n) {
  if (events_.count(n.event)) return;
  const ArbitrateDecl* port = n.rule_decl->port;
  if (!port) return;  // the rule's port did not resolve: reported there
  std::vector<std::string> activity = activity_events(*port);
  for (const std::string& act : activity)
    if (act == n.event) return;
  std::vector<std::string> candidates = event_names_;
  candidates.insert(candidates.end(), activity.begin(), activity.end());
  unknown(n.event_loc,
          "unknown event '" + n.event + "' in " + port->port.qualified() +
              ": name a declared event or the activity event act_RULE of a rule with a `hold` "
              "there",
          diag::UnknownEvent, n.event, candidates);
}

// `only RULE after OTHER;` (and a response's trigger and rule, and a spacing after another
// rule): two different rules of one port, because the model checker unrolls one port's run
// (docs/design.md#properties-over-time).
void Sema::check_precedence(TemporalDecl& n) {
  n.other_decl = unique_rule(n.other, n.other_loc, shape_name(n.kind));
  if (!n.rule_decl || !n.other_decl) return;
  if (n.rule_decl == n.other_decl) {
    error(n.other_loc, same_rule_fix(n), diag::TemporalPair);
  } else if (n.rule_decl->port != n.other_decl->port && n.rule_decl->port && n.other_decl->port) {
    error(n.other_loc,
          "'" + n.rule + "' goes into " + n.rule_decl->port->port.qualified() + " but '" + n.other +
              "' into " + n.other_decl->port->port.qualified() + "; " + pair_shape(n.kind) +
              " relates two rules of one port (the model checker follows one port's messages)",
          diag::TemporalPair);
  }
  if (n.rule_decl == n.other_decl || n.rule_decl->port != n.other_decl->port)
    n.rule_decl = n.other_decl = nullptr;  // reported (or a port reported): lowering skips it
}

const ArbitrateDecl* Sema::arbitrated_port(PortRef& ref, const std::string& use) {
  if (!resolve_port(ref, "destination", use)) return nullptr;
  for (const ArbitrateDecl& a : spec_.arbitrations)
    if (a.port.qualified() == ref.qualified()) return &a;
  error(ref.loc,
        ref.qualified() + " has no `arbitrate` block: " + use +
            " is about the rules that deliver into an arbitrated port",
        diag::NotArbitrated);
  return nullptr;
}

// `stable M.p for D;`: M.p is an arbitrated port (its deliveries are what switches).
void Sema::check_stability(TemporalDecl& n) {
  check_duration(n.window, "the `for` period");
  n.port_decl = arbitrated_port(n.port, "a `stable` property");
}

void Sema::check_temporal(TemporalDecl& n) {
  if (n.kind == TemporalDecl::Kind::Stability) return check_stability(n);
  if (n.kind == TemporalDecl::Kind::Response) return check_response(n);
  if (n.kind == TemporalDecl::Kind::Spacing) check_duration(n.window, "the `within` window");
  n.rule_decl = unique_rule(n.rule, n.rule_loc, shape_name(n.kind));
  // The event is looked up in the rule's port: without the rule there is nothing to say.
  if (n.kind == TemporalDecl::Kind::Absence && n.rule_decl) check_absence_event(n);
  bool pair = n.kind == TemporalDecl::Kind::Precedence ||
              (n.kind == TemporalDecl::Kind::Spacing && !n.other.empty());
  if (pair) check_precedence(n);
}

}  // namespace arbc::frontend
