#include "verify/port_checks.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/body_spec_text.h"
#include "core/join.h"
#include "verify/claim_test.h"
#include "verify/data_assert.h"
#include "verify/data_pair.h"
#include "verify/dead_rule.h"
#include "verify/delivery_order.h"
#include "verify/replay.h"

namespace arbc::verify {
namespace {

std::string list(const std::vector<std::string>& items) {
  return items.empty() ? "none" : join(items);
}

std::string state_text(const EventState& s) {
  return "present: " + list(s.present) + "; absent: " + list(s.absent);
}

const std::string& rule_name(const ScopedRule& r) { return r.connection->name; }

// A rule written `when false` whose monitor sets or unsets events (a `script` may: its Lua is
// not analysed) is an event feed by design: the runtime runs accept before the decision, so it
// changes the container on every message and delivers none. `arbc import yarp` writes a YARP
// monitor that only sets events this way (docs/yarp.md#moving-to-a-spec). Its `by priority`
// activity event does not count: that is set only by a delivery.
bool feeds_events(const model::Connection& c) {
  if (!(c.constraint == Constraint::constant(false))) return false;
  if (c.opaque || !c.unsets.empty()) return true;
  return std::any_of(c.sets.begin(), c.sets.end(),
                     [&](const std::string& e) { return e != c.activity_event; });
}

// Does `c` hold whatever the events are (`true`, `e_ball or not e_ball`)? Decided by the
// runtime's evaluator on every state of the events it reads, so only for a few of them.
bool holds_whatever_the_events(const Constraint& c) {
  std::set<std::string> read;
  c.collect_events(read);
  std::vector<std::string> events(read.begin(), read.end());
  if (events.size() > 10) return false;
  for (unsigned bits = 0; bits < (1u << events.size()); ++bits) {
    std::vector<std::string> present;
    for (size_t i = 0; i < events.size(); ++i)
      if (bits & (1u << i)) present.push_back(events[i]);
    if (!runtime_holds(c, present)) return false;
  }
  return true;
}

// Why rule r holds (or fails) in the state: its constraint, the events it reads, the events
// its own monitor sets or unsets before the decision, and its activity event.
Note explain_rule(const ScopedRule& r, const std::vector<std::string>& present, bool holds) {
  const Constraint& when = r.connection->constraint;
  std::string m = "'" + rule_name(r) + "' " + (holds ? "holds" : "does not hold") + ": `" +
                  when.to_string() + "` with " + describe_state(when, present);
  // A constraint that cannot be false is the overlap's cause however the events fall: say so
  // rather than let the state look like the reason.
  if (holds && holds_whatever_the_events(when)) {
    std::set<std::string> read;
    when.collect_events(read);
    m = "'" + rule_name(r) + "' holds in every state: `" + when.to_string() + "` " +
        (read.empty() ? "reads no events" : "is true whatever the events");
  }
  if (!r.forced_present.empty()) {
    m += "; its monitor sets " + list(r.forced_present) + " on every accepting path";
  }
  if (!r.forced_absent.empty()) {
    m += "; its monitor unsets " + list(r.forced_absent) + " on every accepting path";
  }
  if (!r.activity.empty()) m += "; its delivery sets " + r.activity + " (by priority)";
  return {m, r.connection->loc};
}

// The domain (invariants, exclusive groups) holds in the state, by the runtime's evaluator.
bool domain_holds(const PortScope& scope, const std::vector<std::string>& present) {
  return std::all_of(scope.domain.begin(), scope.domain.end(),
                     [&](const DomainConstraint& d) { return runtime_holds(d.formula, present); });
}

Finding internal_error(const PortScope& scope, const std::string& what, const EventState& state) {
  Finding f;
  f.check = kCheckInternal;
  f.severity = Severity::Error;
  f.port = scope.port->port;
  f.loc = scope.port->loc;
  f.message = "internal error: Z3 and the runtime's constraint evaluator disagree on " + what +
              " in the state " + state_text(state) + "; please report this bug";
  f.counterexample = state;
  return f;
}

class PortChecker {
 public:
  PortChecker(const PortScope& scope, const VerifyOptions& options, z3::context& ctx,
              Clock::time_point deadline, DataQuery& data, ReplayData& replay, PortResult& result)
      : scope_(scope),
        options_(options),
        data_(data),
        replay_(replay),
        solver_(scope, ctx, deadline),
        shortcut_(scope),
        result_(result) {}

  void run() {
    check_dead();
    check_exclusive();
    if (scope_.port->complete) check_complete();
    for (const model::Assertion& a : scope_.port->asserts) check_assert(a);
    result_.solver_queries = solver_.queries() + data_queries_;
  }

 private:
  int rule_index(const std::string& name) const {
    for (size_t i = 0; i < scope_.rules.size(); ++i) {
      if (rule_name(scope_.rules[i]) == name) return static_cast<int>(i);
    }
    return -1;
  }

  void unknown(const std::string& what, const std::string& reason = "") {
    if (!result_.unknown_reason.empty()) return;  // one unknown finding per port is enough
    result_.unknown_reason = reason.empty() ? solver_.unknown_reason() : reason;
    Finding f;
    f.check = kCheckUnknown;
    f.severity = Severity::Error;
    f.port = scope_.port->port;
    f.loc = scope_.port->loc;
    f.message = "could not decide " + what + " for " + scope_.port->port + " (" +
                result_.unknown_reason + "); an unknown verdict never passes";
    f.notes.push_back({"raise --timeout, or split the port's rules", {}});
    result_.findings.push_back(std::move(f));
  }

  void check_dead() {
    std::vector<std::string> dead;
    size_t delivering = 0;
    for (size_t i = 0; i < scope_.rules.size(); ++i) {
      const ScopedRule& r = scope_.rules[i];
      bool feed = feeds_events(*r.connection);
      delivering += !feed;
      Known known = shortcut_.can_hold(static_cast<int>(i));
      if (known == Known::Yes) continue;
      Answer a = known == Known::No ? Answer::Unsat : solver_.can_hold(static_cast<int>(i));
      if (a == Answer::Unknown)
        return unknown("whether rule '" + rule_name(r) + "' can be selected");
      if (a == Answer::Sat) continue;
      if (feed) {
        result_.findings.push_back(feed_note(r));
        continue;
      }
      dead.push_back(rule_name(r));
      result_.findings.push_back(
          dead_rule_finding(r, scope_.port->port, !scope_.domain.empty(), options_.strict));
    }
    if (std::optional<Finding> f = dead_port_finding(scope_, dead, delivering, options_.strict))
      result_.findings.push_back(std::move(*f));
  }

  // A verdict about rule `r` rests on its message data. Where its body reads list elements at
  // an index it does not know (DataQuery::bounded), the data answers hold for lists of at most
  // --list-bound elements, which the verdict says. A rule whose body then accepts no such
  // message looks dead by data, and every pair it is in exclusive by data, while a longer list
  // may pass it: a warning, once per rule.
  void bounded_by_lists(const ScopedRule& r) {
    const model::Connection& c = *r.connection;
    if (!data_.opaque_reason(c).empty() || !data_.bounded(c)) return;
    result_.list_bound = options_.list_bound;
    if (!warned_bound_.insert(&c).second) return;
    DataWitness w;
    DataCore core;
    ++data_queries_;
    if (data_.ask({{&c, nullptr}}, &w, &core) != Answer::Unsat) return;
    Finding f;
    f.check = kCheckListBound;
    f.severity = options_.strict ? Severity::Error : Severity::Warning;
    f.strict = options_.strict;
    f.port = scope_.port->port;
    f.rules = {rule_name(r)};
    f.loc = c.loc;
    std::string n = std::to_string(options_.list_bound);
    f.message = "rule '" + rule_name(r) + "' of " + scope_.port->port + " accepts no " + c.source +
                " message whose lists have at most " + n + " elements (--list-bound " + n +
                "): what it accepts, the proof does not see";
    f.notes.push_back(
        {"raise the bound past the lists it needs (--list-bound N), or fix its "
         "`accept`s if it should accept short lists too",
         {}});
    result_.findings.push_back(std::move(f));
  }

  // A rule that says it never delivers and does something to the container is there for that
  // (feeds_events): removing it would take its events away from the other rules. So it is a
  // note, which --strict leaves alone, that says what the rule does.
  Finding feed_note(const ScopedRule& r) const {
    const model::Connection& c = *r.connection;
    Finding f;
    f.check = kCheckDead;
    f.severity = Severity::Note;
    f.port = scope_.port->port;
    f.rules = {rule_name(r)};
    f.loc = c.loc;
    f.message = "rule '" + rule_name(r) + "' of " + scope_.port->port +
                " never delivers (`when false`): it is an event feed, run on each message for "
                "the events its " +
                (c.opaque ? "script" : "body") + " sets or unsets";
    f.notes.push_back(
        {"nothing to fix if it is meant to feed events, as `arbc import yarp` writes a YARP "
         "monitor whose accept never returns true; to deliver its messages, give it a `when` "
         "that can hold",
         {}});
    return f;
  }

  void check_exclusive() {
    // Priority-encoded ports (each rule a cube clashing with every other) are settled by bit
    // operations; a 200-rule port then costs microseconds instead of a solver query.
    if (shortcut_.pairwise_disjoint()) return;
    Answer a = solver_.at_least_two_hold();
    if (a == Answer::Unknown) return unknown("whether two rules can be selected together");
    if (a == Answer::Unsat) return;
    std::vector<std::pair<int, int>> pairs;
    auto known = [this](int i, int j) { return shortcut_.can_hold_together(i, j); };
    if (solver_.overlapping_pairs(known, pairs) == Answer::Unknown) {
      unknown("which rules overlap");
      if (pairs.empty()) {
        // The at-least-two query already refuted the port: say so even without a pair.
        Finding f;
        f.check = kCheckExclusive;
        f.severity = Severity::Error;
        f.port = scope_.port->port;
        f.loc = scope_.port->loc;
        f.message = "two rules of " + scope_.port->port +
                    " can be selected in one state (which ones was not found in time)";
        result_.findings.push_back(std::move(f));
      }
    }
    refine_by_deliveries(pairs);
    std::map<std::pair<int, int>, DataPair> data = refine_by_data(pairs);
    result_.overlapping_pairs = static_cast<int>(pairs.size());
    int last = -1;  // index of the last reported pair's finding
    for (const auto& [i, j] : pairs) {
      if (result_.reported_pairs >= options_.max_pairs_per_port) break;
      std::optional<std::vector<std::string>> present = solver_.minimal_state({i, j}, {});
      if (!present) {
        if (solver_.last_answer() == Answer::Unknown) unknown("a minimal counterexample");
        continue;
      }
      const ScopedRule& ri = scope_.rules[static_cast<size_t>(i)];
      const ScopedRule& rj = scope_.rules[static_cast<size_t>(j)];
      EventState state = state_of(scope_, *present);
      if (!runtime_holds(ri.effective_guard, *present) ||
          !runtime_holds(rj.effective_guard, *present) || !domain_holds(scope_, *present)) {
        result_.findings.push_back(internal_error(
            scope_, "whether '" + rule_name(ri) + "' and '" + rule_name(rj) + "' both hold",
            state));
        continue;
      }
      auto d = data.find({i, j});
      result_.findings.push_back(overlap_finding(ri, rj, *present, std::move(state),
                                                 d == data.end() ? nullptr : &d->second));
      ++result_.reported_pairs;
      last = static_cast<int>(result_.findings.size()) - 1;
    }
    int rest = result_.overlapping_pairs - result_.reported_pairs;
    if (last >= 0 && rest > 0) {
      result_.findings[static_cast<size_t>(last)].notes.push_back(
          {std::to_string(rest) + " more overlapping pair" + (rest == 1 ? "" : "s") + " of " +
               scope_.port->port + " not shown (at most " +
               std::to_string(options_.max_pairs_per_port) + " per port)",
           {}});
    }
  }

  // The finding of two rules selected in one state, with the message both accept when they
  // read one source (`d`), and the counterexample as a test that states the port's exclusivity.
  Finding overlap_finding(const ScopedRule& ri, const ScopedRule& rj,
                          const std::vector<std::string>& present, EventState state, DataPair* d) {
    Finding f;
    f.check = kCheckExclusive;
    f.severity = Severity::Error;
    f.port = scope_.port->port;
    f.rules = {rule_name(ri), rule_name(rj)};
    f.loc = ri.connection->loc;
    f.message = "rules '" + rule_name(ri) + "' and '" + rule_name(rj) + "' of " +
                scope_.port->port + " can both be selected in one state";
    f.notes.push_back({"counterexample (fewest events present): " + state_text(state), {}});
    f.notes.push_back(explain_rule(ri, present, true));
    f.notes.push_back(explain_rule(rj, present, true));
    f.notes.push_back(
        {"make the constraints exclusive (e.g. `not EVENT` in one of them), or "
         "declare the `invariant` or `exclusive` group that rules this state out",
         {}});
    DecisionReplay replay{
        "counterexample: " + f.rules[0] + " and " + f.rules[1] + " selected together in " + f.port,
        state,
        {ri.connection, rj.connection},
        {std::nullopt, std::nullopt},
        exclusive_claim(f.port)};
    f.counterexample = std::move(state);
    if (d) {
      for (Note& n : d->notes) f.notes.push_back(std::move(n));
      if (d->example) f.messages.push_back(std::move(*d->example));
      replay.messages = {d->message, d->message};
    }
    if (ri.connection->source == rj.connection->source && !replay.messages[0])
      f.not_replayable = "'" + f.rules[0] + "' and '" + f.rules[1] +
                         "' read one source, and no message both accept from a fresh monitor "
                         "is known";
    else
      f.replay_test =
          decision_test(replay, replay_.data(), options_.test_replayer, &f.not_replayable);
    return f;
  }

  // Drops from `pairs` those whose deliveries keep each other out (verify/delivery_order.h).
  void refine_by_deliveries(std::vector<std::pair<int, int>>& pairs) {
    std::vector<std::pair<int, int>> kept;
    for (const auto& [i, j] : pairs) {
      std::string text;
      switch (delivery_order(solver_, scope_, i, j, &text)) {
        case DeliveryOrder::KeepsOut:
          result_.exclusive_by_delivery.push_back(text);
          continue;
        case DeliveryOrder::Unknown:
          unknown("whether '" + rule_name(scope_.rules[static_cast<size_t>(i)]) + "' and '" +
                  rule_name(scope_.rules[static_cast<size_t>(j)]) + "' keep each other out");
          continue;
        case DeliveryOrder::Overlap:
          kept.emplace_back(i, j);
      }
    }
    pairs = std::move(kept);
  }

  // Drops from `pairs` those that no one message can select together (same source, both
  // bodies encodable, no message accepted by both: "exclusive by data"), and returns what the
  // data says about the others (a message both accept, or why data was not considered).
  std::map<std::pair<int, int>, DataPair> refine_by_data(std::vector<std::pair<int, int>>& pairs) {
    std::map<std::pair<int, int>, DataPair> out;
    std::vector<std::pair<int, int>> kept;
    for (const auto& [i, j] : pairs) {
      const model::Connection& a = *scope_.rules[static_cast<size_t>(i)].connection;
      const model::Connection& b = *scope_.rules[static_cast<size_t>(j)].connection;
      DataPair d = same_message_pair(data_, options_.runner, a, b);
      data_queries_ += d.queries;
      switch (d.kind) {
        case DataPair::Kind::Exclusive:
          result_.exclusive_by_data.push_back(d.text);
          bounded_by_lists(scope_.rules[static_cast<size_t>(i)]);
          bounded_by_lists(scope_.rules[static_cast<size_t>(j)]);
          continue;
        case DataPair::Kind::Unknown:
          unknown(d.text, data_.unknown_reason());
          continue;
        case DataPair::Kind::Internal:
          result_.findings.push_back(internal_data_error(scope_.port->port, a.loc, d.text));
          continue;
        case DataPair::Kind::Overlap:
        case DataPair::Kind::NotApplicable:
          kept.emplace_back(i, j);
          out.emplace(std::make_pair(i, j), std::move(d));
      }
    }
    pairs = std::move(kept);
    return out;
  }

  void check_complete() {
    std::vector<int> all;
    for (size_t i = 0; i < scope_.rules.size(); ++i) all.push_back(static_cast<int>(i));
    std::optional<std::vector<std::string>> present = solver_.minimal_state({}, all);
    if (!present) {
      if (solver_.last_answer() == Answer::Unknown) unknown("whether some rule is always selected");
      return;
    }
    EventState state = state_of(scope_, *present);
    bool agree = domain_holds(scope_, *present);
    for (const ScopedRule& r : scope_.rules) agree &= !runtime_holds(r.effective_guard, *present);
    if (!agree) {
      result_.findings.push_back(internal_error(scope_, "whether no rule holds", state));
      return;
    }
    Finding f;
    f.check = kCheckComplete;
    f.severity = Severity::Error;
    f.port = scope_.port->port;
    f.loc = scope_.port->loc;
    f.message = "port " + scope_.port->port +
                " is declared complete, but in some state no rule is selected";
    f.notes.push_back({"counterexample (fewest events present): " + state_text(state), {}});
    for (const ScopedRule& r : scope_.rules) f.notes.push_back(explain_rule(r, *present, false));
    f.notes.push_back(
        {"add a rule for this state (e.g. `otherwise`), or declare the invariant "
         "that rules it out",
         {}});
    f.counterexample = std::move(state);
    result_.findings.push_back(std::move(f));
  }

  void check_assert(const model::Assertion& a) {
    int r = rule_index(a.rule);
    if (a.emitted) {  // over data (verify/data_assert.h)
      DataAssertOutcome d = check_data_assert(scope_, r, a, solver_, data_, options_.runner);
      if (!d.unknown.empty()) unknown(d.unknown, d.unknown_reason);
      if (d.finding && d.message) {  // kept as a test that states the assert (claim_test.h)
        DecisionReplay replay{"counterexample: " + a.rule + " delivers a value for which `" +
                                  model::body_expr_spec_text(*a.emitted, "emitted") + "` is false",
                              *d.finding->counterexample,
                              {scope_.rules[static_cast<size_t>(r)].connection},
                              {d.message},
                              assert_claim(scope_.port->port, a)};
        d.finding->replay_test = decision_test(replay, replay_.data(), options_.test_replayer,
                                               &d.finding->not_replayable);
      }
      if (d.finding) result_.findings.push_back(std::move(*d.finding));
      // Holds of what the rule delivers for messages with lists of at most the bound.
      if (!d.finding && r >= 0) {
        const ScopedRule& rule = scope_.rules[static_cast<size_t>(r)];
        bounded_by_lists(rule);
        // The property itself may read past the bound (`emitted[5]` with --list-bound 4): then
        // the answer holds for short lists only, and the port's verdict says so, as build
        // records it for the rule (DataQuery::bounded_rules). drt seed 19001 found a report
        // that did not.
        if (data_.opaque_reason(*rule.connection).empty() &&
            data_.bounded(*rule.connection, &*a.emitted, /*negate=*/true))
          result_.list_bound = options_.list_bound;
      }
      return;
    }
    std::optional<std::vector<std::string>> present = solver_.minimal_state({r}, {}, &a.property);
    if (!present) {
      if (solver_.last_answer() == Answer::Unknown) unknown("the assert on '" + a.rule + "'");
      return;
    }
    const ScopedRule& rule = scope_.rules[static_cast<size_t>(r)];
    EventState state = state_of(scope_, *present);
    if (!runtime_holds(rule.effective_guard, *present) || runtime_holds(a.property, *present) ||
        !domain_holds(scope_, *present)) {
      result_.findings.push_back(internal_error(scope_, "the assert on '" + a.rule + "'", state));
      return;
    }
    Finding f;
    f.check = kCheckAssert;
    f.severity = Severity::Error;
    f.port = scope_.port->port;
    f.rules = {a.rule};
    f.loc = a.loc;
    f.message = "assert " + scope_.port->port + ": " + a.rule + " -> " + a.property.to_string() +
                " can fail: '" + a.rule + "' can be selected while `" + a.property.to_string() +
                "` is false";
    f.notes.push_back({"counterexample (fewest events present): " + state_text(state), {}});
    f.notes.push_back(explain_rule(rule, *present, true));
    f.notes.push_back({"strengthen the `when` of '" + a.rule + "' with the property", {}});
    DecisionReplay replay{
        "counterexample: " + a.rule + " delivers while `" + a.property.to_string() + "` is false",
        state,
        {rule.connection},
        {std::nullopt},
        assert_claim(f.port, a)};
    f.replay_test =
        decision_test(replay, replay_.data(), options_.test_replayer, &f.not_replayable);
    f.counterexample = std::move(state);
    result_.findings.push_back(std::move(f));
  }

  const PortScope& scope_;
  const VerifyOptions& options_;
  DataQuery& data_;
  ReplayData& replay_;
  int data_queries_ = 0;
  std::set<const model::Connection*> warned_bound_;  // rules bounded_by_lists has looked at
  PortSolver solver_;
  CubeShortcut shortcut_;
  PortResult& result_;
};

}  // namespace

void run_port_checks(const PortScope& scope, const VerifyOptions& options, z3::context& ctx,
                     Clock::time_point deadline, DataQuery& data, ReplayData& replay,
                     PortResult& result) {
  result.port = scope.port->port;
  result.by_priority = scope.port->by_priority;
  result.complete = scope.port->complete;
  result.loc = scope.port->loc;
  result.asserts = static_cast<int>(scope.port->asserts.size());
  // A feed stays in the encoding (its effective guard is false, so it overlaps nothing) but
  // is not named among the rules the proof says are never selected together.
  for (const ScopedRule& r : scope.rules)
    (feeds_events(*r.connection) ? result.feeds : result.rules).push_back(rule_name(r));
  result.events = scope.events;
  for (const DomainConstraint& d : scope.domain) {
    if (d.is_invariant) {
      result.invariants.push_back(d.text);
    } else {
      ++result.exclusive_groups;
    }
  }
  PortChecker(scope, options, ctx, deadline, data, replay, result).run();
}

}  // namespace arbc::verify
