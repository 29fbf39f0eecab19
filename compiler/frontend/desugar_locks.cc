#include "compiler/frontend/desugar_locks.h"

#include <map>

#include "core/check_ids.h"

namespace arbc::frontend {

namespace {

using ast::Expr;
using ast::ExprPtr;
using ast::Loc;

ExprPtr node(Expr::Kind kind, const Loc& at) {
  auto e = std::make_unique<Expr>();
  e->kind = kind;
  e->loc = at;
  return e;
}

ExprPtr name(const std::string& text, const Loc& at) {
  ExprPtr e = node(Expr::Kind::Name, at);
  e->text = text;
  return e;
}

// What a lock's name means where a constraint reads it.
struct LockMeaning {
  std::string engaged, heard;  // heard: empty for a lock that silence opens
  ExprPtr expr(const Loc& at) const {
    if (heard.empty()) return name(engaged, at);
    ExprPtr silent = node(Expr::Kind::Unary, at);
    silent->op = ast::operator_spelling("not");
    silent->args.push_back(name(heard, at));
    ExprPtr e = node(Expr::Kind::Binary, at);
    e->op = ast::operator_spelling("or");
    e->args.push_back(name(engaged, at));
    e->args.push_back(std::move(silent));
    return e;
  }
};
using Locks = std::map<std::string, LockMeaning, std::less<>>;

// The default predicate: the message itself for a `bool` port, else its `data` field (the layout
// of std_msgs/msg/Bool); sema says what is wrong with either.
ExprPtr default_predicate(const ast::Spec& spec, const ast::LockDecl& l) {
  ExprPtr message = name(l.source.port, l.source.loc);
  for (const ast::ModuleDecl& m : spec.modules) {
    if (m.name != l.source.module) continue;
    const ast::PortDecl* p = m.find_port(l.source.port);
    if (p && p->type.kind == ast::TypeExpr::Kind::Bool) return message;
  }
  ExprPtr data = node(Expr::Kind::Field, l.source.loc);
  data->text = "data";
  data->args.push_back(std::move(message));
  return data;
}

ast::DerivedEventDecl derived(std::string event, const ast::LockDecl& l, ExprPtr predicate) {
  ast::DerivedEventDecl e;
  e.name = std::move(event);
  e.source = l.source;
  e.predicate = std::move(predicate);
  e.loc = l.loc;
  return e;
}

// The lock's two events, added to the spec's derived events; its meaning.
LockMeaning declare(ast::Spec& spec, ast::LockDecl& l, std::vector<Diagnostic>& out) {
  LockMeaning m{l.name + "_engaged", l.open_after ? "" : l.name + "_heard"};
  ExprPtr predicate = l.predicate ? std::move(l.predicate) : default_predicate(spec, l);
  ast::DerivedEventDecl engaged = derived(m.engaged, l, std::move(predicate));
  if (l.open_after) {
    if (l.open_after->word != "open")
      out.push_back(make_diagnostic(
          Severity::Error, l.open_after->word_loc,
          "`otherwise " + l.open_after->word + " after ...` on a lock: silence can only open it: " +
              "`otherwise open after D` (an event's is `otherwise absent after D`)",
          diag::Lock.text()));
    engaged.fail_open = std::move(l.open_after);
    engaged.fail_open->word = "absent";  // the engaged event counts as absent: the lock opens
  }
  spec.derived_events.push_back(std::move(engaged));
  if (!m.heard.empty()) {
    ExprPtr always = node(Expr::Kind::Bool, l.loc);
    always->boolean = true;
    ast::DerivedEventDecl heard = derived(m.heard, l, std::move(always));
    if (l.timeout) heard.lifetime = std::move(l.timeout);
    spec.derived_events.push_back(std::move(heard));
  }
  return m;
}

// Every name of a lock in `e` (a constraint) replaced by what it means.
void substitute(ExprPtr& e, const Locks& locks) {
  if (!e) return;
  if (e->kind == Expr::Kind::Name) {
    auto it = locks.find(e->text);
    if (it != locks.end()) e = it->second.expr(e->loc);
    return;
  }
  for (ExprPtr& a : e->args) substitute(a, locks);
}

// `never R while LOCK;`: the engaged event by absence, the heard event by an assert on R's port.
void expand_absence(ast::Spec& spec, ast::TemporalDecl& t, const LockMeaning& m) {
  t.event = m.engaged;
  if (m.heard.empty()) return;
  for (const ast::ArbitrateDecl& a : spec.arbitrations) {
    for (const ast::Rule& r : a.rules) {
      if (r.name != t.rule) continue;
      ast::AssertDecl heard;
      heard.port = a.port;
      heard.rule = t.rule;
      heard.rule_loc = t.rule_loc;
      heard.property = name(m.heard, t.event_loc);
      heard.loc = t.loc;
      spec.asserts.push_back(std::move(heard));
      return;  // a rule name two ports share is sema's error (temporal-rule)
    }
  }
}

// Where one event is needed: a lock that silence opens is one event (its engaged one), and
// stands for it; a lock that fails closed is refused, and its engaged event put in its place so
// that sema does not also call the name unknown.
void single_event(std::string& event, const Loc& at, const Locks& locks, const char* where,
                  std::vector<Diagnostic>& out) {
  auto it = locks.find(event);
  if (it == locks.end()) return;
  if (!it->second.heard.empty())
    out.push_back(make_diagnostic(
        Severity::Error, at,
        "'" + event + "' is a lock, which stands for two events (" + it->second.engaged +
            " while its last message says engaged, " + it->second.heard +
            " while its publisher is heard): " + where + " needs one event; name the one you mean",
        diag::Lock.text()));
  event = it->second.engaged;
}

void single_event_uses(ast::Spec& spec, const Locks& locks, std::vector<Diagnostic>& out) {
  for (ast::TemporalDecl& t : spec.temporal) {
    if (t.kind != ast::TemporalDecl::Kind::Response) continue;
    // Sema moves an event trigger from `other` to `event`; here it is still in `other`.
    single_event(t.other, t.other_loc, locks, "a response's trigger", out);
    single_event(t.event, t.event_loc, locks, "a response's trigger", out);
  }
  for (ast::ExclusiveDecl& x : spec.exclusives)
    for (ast::EventName& e : x.events)
      single_event(e.name, e.loc, locks, "an exclusive group", out);
  for (ast::AssumeDecl& a : spec.assumptions)
    single_event(a.event, a.event_loc, locks, "an assumption", out);
}

// Where `name` is declared as an event already (its line), or 0. A lock of that name would
// shadow the event wherever a constraint reads it.
int event_line(const ast::Spec& spec, const std::string& name) {
  for (const ast::EventDecl& e : spec.events)
    for (const ast::EventName& n : e.names)
      if (n.name == name) return n.loc.line;
  for (const ast::DerivedEventDecl& e : spec.derived_events)
    if (e.name == name) return e.loc.line;
  for (const ast::StatusEventDecl& e : spec.status_events)
    for (const ast::StatusEventDecl::Entry& x : e.entries)
      if (x.event == name) return x.loc.line;
  return 0;
}

// A lock reads a module's output (an e-stop's, a pause switch's); a lock that is declared twice,
// or under an event's name, is refused before it becomes two events (whose duplicates sema would
// name without the lock). False when `l` is not to be declared.
bool declarable(const ast::Spec& spec, const ast::LockDecl& l, const Locks& locks,
                std::vector<Diagnostic>& out) {
  auto refuse = [&](const Loc& at, std::string message, DiagId id) {
    out.push_back(make_diagnostic(Severity::Error, at, std::move(message), id.text()));
    return false;
  };
  if (locks.count(l.name))
    return refuse(l.loc, "lock '" + l.name + "' is declared twice: rename one of them",
                  diag::Duplicate);
  if (int line = event_line(spec, l.name))
    return refuse(l.loc,
                  "'" + l.name + "' is an event already (line " + std::to_string(line) +
                      "): a lock needs a name of its own",
                  diag::Duplicate);
  for (const ast::ModuleDecl& m : spec.modules) {
    const ast::PortDecl* p = m.name == l.source.module ? m.find_port(l.source.port) : nullptr;
    if (p && p->direction == model::Direction::In)
      return refuse(l.source.loc,
                    "a lock reads what a module publishes (an e-stop's state, a pause switch): " +
                        l.source.qualified() + " is an input of " + m.name,
                    diag::Lock);
  }
  return true;
}

}  // namespace

void desugar_locks(ast::Spec& spec, std::vector<Diagnostic>& out) {
  if (spec.locks.empty()) return;
  Locks locks;
  for (ast::LockDecl& l : spec.locks)
    if (declarable(spec, l, locks, out)) locks[l.name] = declare(spec, l, out);
  spec.locks.clear();
  for (ast::ArbitrateDecl& a : spec.arbitrations)
    for (ast::Rule& r : a.rules) substitute(r.when, locks);
  for (ast::AssertDecl& a : spec.asserts) substitute(a.property, locks);
  for (ast::InvariantDecl& i : spec.invariants) substitute(i.formula, locks);
  single_event_uses(spec, locks, out);
  for (ast::TemporalDecl& t : spec.temporal) {
    substitute(t.condition, locks);
    auto it = locks.find(t.event);
    if (t.kind == ast::TemporalDecl::Kind::Absence && it != locks.end())
      expand_absence(spec, t, it->second);
  }
}

}  // namespace arbc::frontend
