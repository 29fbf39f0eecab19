// Semantic checks of `test` declarations (docs/testing.md): every name resolves against the
// app, every message literal is a constant value of its port's type, every time is a duration,
// and a test `on RULE` stays on that rule's ports.
#include <algorithm>
#include <cmath>
#include <map>

#include "compiler/frontend/expectation_hint.h"
#include "compiler/frontend/literal_value.h"
#include "compiler/frontend/rule_drop_reasons.h"
#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/test_contradiction.h"
#include "compiler/frontend/type_rules.h"
#include "core/join.h"
#include "runtime/drop_reason.h"

namespace arbc::frontend {

using namespace ast;

namespace {

// The drop reasons of docs/runtime.md#drop-reasons a test can expect, as `expect RULE drops
// "reason"` names them: all but lost-in-transit, which only DDS between processes reports.
std::vector<std::string> test_drop_reasons() {
  std::vector<std::string> out;
  for (const DropReasonInfo& r : kDropReasons) {
    if (r.reason != DropReason::LostInTransit) out.push_back(r.name);
  }
  return out;
}
const std::vector<std::string> kTestDropReasons = test_drop_reasons();

}  // namespace

void Sema::check_tests() {
  std::map<std::string, const TestDecl*> names;
  for (TestDecl& t : spec_.tests) {
    auto [it, added] = names.emplace(t.name, &t);
    if (!added) {
      error(t.loc,
            "test \"" + t.name + "\" is already defined at line " +
                std::to_string(it->second->loc.line) + ": rename one of them",
            diag::Duplicate);
    }
    if (!t.on.empty()) t.on_rule = find_test_rule(t.on, t.on_loc);
    for (TestStep& s : t.steps) check_test_step(t, s);
    for (TestExpect& e : t.expects) check_test_expect(t, e);
    if (t.expects.empty()) report_expects_nothing(t);
    if (auto pair = contradicting_receives(t)) {
      Diagnostic& d = error(pair->first->loc,
                            "this expectation contradicts `expect " + pair->second->text +
                                "` (line " + std::to_string(pair->second->loc.line) +
                                "): no run can satisfy both, so the test can never pass",
                            diag::TestWindow);
      Diagnostic note;
      note.severity = Severity::Note;
      note.message = "give `receives nothing` a window that leaves this one out";
      d.notes.push_back(std::move(note));
    }
  }
}

// A test without an expectation passes whatever the app does: its green would prove nothing,
// so, like a test that can never pass, it is an error before anything runs.
void Sema::report_expects_nothing(const TestDecl& t) {
  Diagnostic& d = error(t.loc,
                        "test \"" + t.name +
                            "\" expects nothing, so it would pass whatever the app does: add "
                            "an `expect`",
                        diag::TestExpect);
  Diagnostic note;
  note.severity = Severity::Note;
  std::string hint = expectation_hint(t, spec_);
  note.message =
      (hint.empty() ? "" : "for example `" + hint + "`. ") +
      std::string(
          "A test can expect that a port receives a value (or nothing), that "
          "a rule drops a message or delivers (or not), that a property over time holds, or that "
          "events hold at a time");
  d.notes.push_back(std::move(note));
}

const Rule* Sema::find_test_rule(const std::string& name, const Loc& loc) {
  std::vector<const Rule*> found;
  std::vector<std::string> all;
  for (const ArbitrateDecl& a : spec_.arbitrations) {
    for (const Rule& r : a.rules) {
      all.push_back(r.name);
      if (r.name == name) found.push_back(&r);
    }
  }
  if (found.empty()) {
    Diagnostic& d = unknown(loc, "no rule is named '" + name + "'", diag::UnknownRule, name, all);
    if (d.notes.empty() && !all.empty()) {  // nothing close: a test names a rule, not a module
      Diagnostic note;
      note.severity = Severity::Note;
      std::vector<std::string> quoted;
      for (const std::string& r : all) quoted.push_back("'" + r + "'");
      note.message = all.size() == 1 ? "the only rule is " + quoted[0]
                                     : "the rules are " + join(quoted, ", ", " and ");
      d.notes.push_back(std::move(note));
    }
    return nullptr;
  }
  if (found.size() > 1) {
    error(loc,
          "rule name '" + name + "' is used by " + std::to_string(found.size()) +
              " ports; a test can name only a rule whose name is unique: rename one",
          diag::TestPort);
  }
  return found.front();
}

void Sema::check_test_time(Duration& d, const std::string& what) {
  Expr& e = *d.expr;
  if (e.kind == Expr::Kind::Number) {
    check_duration(d, what);  // reports the missing unit
    return;
  }
  Scope empty;
  check_expr(e, empty);
  if (!e.type) return;
  double seconds =
      e.kind == Expr::Kind::Duration ? e.number : (e.constant ? e.constant->number : 0);
  if (!e.is_duration && e.kind != Expr::Kind::Duration) {
    error(e.loc, what + " must be a time such as 1.5s or 200ms", diag::Duration);
  } else if (!(seconds >= 0) || !std::isfinite(seconds)) {
    error(e.loc, what + " must be a time >= 0s", diag::Duration);
  } else if (std::optional<Nanos> n = duration_nanos(e, what)) {
    d.nanos = *n;  // an instant of the run, which counts whole nanoseconds
  }
}

void Sema::check_test_value(Expr& e, const PortRef& port, std::optional<Nanos> at) {
  Scope empty;
  TypePtr want = port.port_decl ? port.port_decl->type.resolved : nullptr;
  if (!desugar_test_stamps(e, want, at)) return;
  check_expr(e, empty);
  if (!e.type || !want) return;
  if (!check_value_fits(e, want,
                        "the value is " + describe(e.type) + ", but " + port.qualified() +
                            " carries " + describe(want),
                        diag::TestValue))
    return;
  std::string why;
  if (!literal_value(e, *want, &why)) error(e.loc, "this value is " + why, diag::TestValue);
}

void Sema::check_test_step(const TestDecl& t, TestStep& s) {
  check_test_time(s.at, "the time of a test step");
  if (s.kind != TestStep::Kind::Input) {
    if (!events_.count(s.event)) {
      unknown(s.event_loc, "unknown event '" + s.event + "'", diag::UnknownEvent, s.event,
              event_names_);
    }
    return;
  }
  if (!resolve_port(s.port, "source", "a test input")) return;
  if (t.on_rule && s.port.qualified() != t.on_rule->source.qualified()) {
    error(s.port.loc,
          "test \"" + t.name + "\" is on rule '" + t.on + "', whose messages come from " +
              t.on_rule->source.qualified() + "; an input on " + s.port.qualified() +
              " would not reach it",
          diag::TestPort);
  }
  check_test_value(*s.value, s.port, s.at.nanos);
}

void Sema::check_test_window(TestWindow& w, bool instant_only) {
  if (!w.present) return;
  check_test_time(w.from, "the start of a window");
  if (!w.to.expr) return;
  if (instant_only) {
    error(w.loc, "an event state is checked at one time: write `at D`, not a window",
          diag::TestWindow);
    return;
  }
  check_test_time(w.to, "the end of a window");
  if (w.to.nanos < w.from.nanos) {
    error(w.loc, "the window ends before it starts: write `within EARLIER..LATER`",
          diag::TestWindow);
  }
}

// A test expecting a drop its rule can never make can never pass: said before it runs, with
// the reason the rule's `when` gives, which is what a newcomer usually means.
void Sema::check_reason_possible(const Rule& rule, const TestExpect& e) {
  std::string why = why_rule_never_drops(rule, e.reason);
  if (why.empty()) return;
  Diagnostic& d = error(e.reason_loc,
                        "rule '" + rule.name + "' never drops a message as \"" + e.reason +
                            "\": " + why + ", so this expectation can never hold",
                        diag::TestReason);
  Diagnostic note;
  note.severity = Severity::Note;
  note.message = "a message the rule's `when` does not select is dropped as \"not-selected\"";
  d.notes.push_back(std::move(note));
}

// `expect exclusive M.p;` and `expect assert M.p: RULE -> EXPR;`: the claims the proof makes
// about single decisions, judged on the run by the runtime's own checks (harness/claim_expect.h).
// One that could not fail there is refused: a `by priority` port claims no exclusivity, and a
// test on one rule runs no other rule of the port.
void Sema::check_test_claim(const TestDecl& t, TestExpect& e) {
  if (e.kind == TestExpect::Kind::Assert) {
    check_assert(*e.assertion);  // over events, or over `emitted` (each delivery of the rule)
    return;
  }
  if (e.kind == TestExpect::Kind::Resource) {
    std::vector<std::string> all;
    for (const ResourceDecl& r : spec_.resources) {
      all.push_back(r.name);
      if (r.name != e.rule) continue;
      if (t.on_rule)
        error(e.loc,
              "test \"" + t.name + "\" runs rule '" + t.on +
                  "' alone: a resource is about rules of two of its ports; remove `on " + t.on +
                  "`",
              diag::TestPort);
      return;
    }
    unknown(e.rule_loc,
            "no resource is named '" + e.rule + "': `expect resource` states the claim of a " +
                "declared `resource` (docs/checks.md#resource)",
            diag::TestClaim, e.rule, all);
    return;
  }
  const ArbitrateDecl* a = arbitrated_port(e.port, "`expect exclusive`");
  if (!a) return;
  if (a->by_priority) {
    error(e.port.loc,
          e.port.qualified() +
              " is arbitrated `by priority`: a higher rule may deliver right after a lower one by "
              "design, so no exclusivity is claimed (docs/design.md#priorities-and-holds)",
          diag::TestClaim);
  } else if (t.on_rule) {
    error(e.loc,
          "test \"" + t.name + "\" runs rule '" + t.on +
              "' alone: exclusivity is about the port's rules together; remove `on " + t.on + "`",
          diag::TestPort);
  }
}

// `expect CONSTRAINT [in M.p] at D;`. M.p must own a container: an arbitrated port, and in a
// test `on RULE` the rule's own, the only one that runs. Which container a bare form reads is
// decided after lowering, where the feeds are known (compiler/lower/test_containers.h).
void Sema::check_test_state(const TestDecl& t, TestExpect& e) {
  e.constraint = check_constraint(*e.value, "an expectation", false);
  if (!e.window.present) {
    error(e.loc, "an event state is checked at a time: add `at D`", diag::TestWindow);
  }
  if (e.port.module.empty() || !resolve_port(e.port, "destination", "an event state")) return;
  const ArbitrateDecl* a = nullptr;
  for (const ArbitrateDecl& d : spec_.arbitrations)
    if (d.port.qualified() == e.port.qualified()) a = &d;
  if (!a) {
    error(e.port.loc,
          e.port.qualified() +
              " has no `arbitrate` block, so no event container: events live in the containers "
              "of arbitrated ports (docs/design.md#feeds)",
          diag::NotArbitrated);
  } else if (t.on_rule && a != t.on_rule->port) {
    error(e.port.loc,
          "test \"" + t.name + "\" runs rule '" + t.on + "' alone: only the container of " +
              t.on_rule->port->port.qualified() + " is there",
          diag::TestPort);
  }
}

void Sema::check_test_expect(const TestDecl& t, TestExpect& e) {
  switch (e.kind) {
    case TestExpect::Kind::Receives:
    case TestExpect::Kind::Nothing:
      if (resolve_port(e.port, "destination", "an expectation") && t.on_rule &&
          e.port.qualified() != t.on_rule->port->port.qualified()) {
        error(e.port.loc,
              "test \"" + t.name + "\" is on rule '" + t.on + "', which delivers only to " +
                  t.on_rule->port->port.qualified(),
              diag::TestPort);
      }
      if (e.value) check_test_value(*e.value, e.port, std::nullopt);
      break;
    case TestExpect::Kind::Drops:
      e.rule_decl = find_test_rule(e.rule, e.rule_loc);
      if (t.on_rule && e.rule_decl && e.rule_decl != t.on_rule) {
        error(e.rule_loc, "test \"" + t.name + "\" runs rule '" + t.on + "' alone", diag::TestPort);
      }
      if (!e.reason.empty() && std::find(kTestDropReasons.begin(), kTestDropReasons.end(),
                                         e.reason) == kTestDropReasons.end()) {
        Diagnostic& d = unknown(e.reason_loc, "unknown drop reason \"" + e.reason + "\"",
                                diag::TestReason, e.reason, kTestDropReasons);
        if (d.notes.empty()) {  // nothing close: the whole list, which is short
          Diagnostic note;
          note.severity = Severity::Note;
          note.message = "a drop reason is one of " + join(kTestDropReasons, ", ", " or ");
          d.notes.push_back(std::move(note));
        }
      } else if (!e.reason.empty() && e.rule_decl) {
        check_reason_possible(*e.rule_decl, e);
      }
      break;
    case TestExpect::Kind::Delivers:
    case TestExpect::Kind::DeliversNothing:
      e.rule_decl = find_test_rule(e.rule, e.rule_loc);
      if (t.on_rule && e.rule_decl && e.rule_decl != t.on_rule) {
        error(e.rule_loc, "test \"" + t.name + "\" runs rule '" + t.on + "' alone", diag::TestPort);
      }
      break;
    case TestExpect::Kind::Property:
      check_temporal(*e.property);
      break;
    case TestExpect::Kind::Exclusive:
    case TestExpect::Kind::Assert:
    case TestExpect::Kind::Resource:
      check_test_claim(t, e);
      break;
    case TestExpect::Kind::State:
      check_test_state(t, e);
      break;
  }
  check_test_window(e.window, e.kind == TestExpect::Kind::State);
}

}  // namespace arbc::frontend
