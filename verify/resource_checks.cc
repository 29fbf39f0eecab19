#include "verify/resource_checks.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "core/join.h"
#include "verify/claim_test.h"
#include "verify/data_pair.h"
#include "verify/delivery_effects.h"
#include "verify/joint_scope.h"

namespace arbc::verify {

namespace {

// A rule into one of the resource's ports.
struct ResourceRule {
  const model::Connection* connection = nullptr;
  size_t port = 0;  // index into the resource's ports
  const PortScope* scope = nullptr;
  const ScopedRule* rule = nullptr;
  int index = 0;  // in its port's scope
};

// Two decisions in a row: `first` delivers a command that uses the resource, then `second`
// decides in the state that delivery left (docs/checks.md#resource). The state is the same but
// for the delivery events the first delivery feeds into the second's port.
struct Order {
  const ResourceRule* first = nullptr;
  const ResourceRule* second = nullptr;
  std::vector<DeliveryEffect> effects;  // on the second's container
  Answer answer = Answer::Unsat;        // can both deliver in this order?
  std::vector<std::string> state;       // Sat: the state before the first (fewest present)
};

class ResourceChecker {
 public:
  ResourceChecker(const model::App& app, const std::vector<PortScope>& scopes,
                  const VerifyOptions& options, z3::context& ctx, Clock::time_point deadline,
                  DataQuery& data, const model::Resource& res, ResourceResult& out)
      : app_(app),
        scopes_(scopes),
        options_(options),
        ctx_(ctx),
        deadline_(deadline),
        data_(data),
        res_(res),
        out_(out) {}

  void run() {
    out_.name = res_.name;
    out_.ports = res_.ports;
    out_.loc = res_.loc;
    std::vector<ResourceRule> rules = resource_rules();
    for (size_t i = 0; i < rules.size(); ++i)
      for (size_t j = i + 1; j < rules.size(); ++j)
        if (rules[i].port != rules[j].port) check_pair(rules[i], rules[j]);
    bool error = false;
    for (const Finding& f : out_.findings)
      error |= f.severity == Severity::Error && f.check != kCheckUnknown;
    out_.verdict = error                          ? Verdict::Refuted
                   : !out_.unknown_reason.empty() ? Verdict::Unknown
                                                  : Verdict::Proved;
  }

 private:
  // The rules into the resource's ports.
  std::vector<ResourceRule> resource_rules() {
    std::vector<ResourceRule> out;
    for (size_t p = 0; p < res_.ports.size(); ++p) {
      for (const PortScope& s : scopes_) {
        if (s.port->port != res_.ports[p]) continue;
        for (const ScopedRule& r : s.rules)
          out.push_back({r.connection, p, &s, &r, static_cast<int>(&r - s.rules.data())});
      }
    }
    return out;
  }

  void unknown(const std::string& what, const std::string& reason) {
    if (!out_.unknown_reason.empty()) return;
    out_.unknown_reason = reason;
    Finding f = base_finding(kCheckUnknown);
    f.message = "could not decide " + what + " for resource '" + res_.name + "' (" + reason +
                "); an unknown verdict never passes";
    out_.findings.push_back(std::move(f));
  }

  Finding base_finding(const char* check) const {
    Finding f;
    f.check = check;
    f.severity = Severity::Error;
    f.loc = res_.loc;
    return f;
  }

  std::string pair_name(const ResourceRule& a, const ResourceRule& b) const {
    return "'" + a.connection->name + "' (into " + res_.ports[a.port] + ") and '" +
           b.connection->name + "' (into " + res_.ports[b.port] + ")";
  }

  const model::BodyExpr* uses() const { return res_.uses ? &*res_.uses : nullptr; }

  JointScope& joint(const ResourceRule& a, const ResourceRule& b);
  void decide_order(const ResourceRule& a, const ResourceRule& b, Order& o);
  std::string effects_text(const Order& o) const;
  bool opaque_pair(const ResourceRule& a, const ResourceRule& b);
  void check_pair(const ResourceRule& a, const ResourceRule& b);
  void by_events(const ResourceRule& a, const ResourceRule& b, const Order& ab, const Order& ba);
  bool never_uses(const ResourceRule& a, const ResourceRule& b, DataWitness w[2]);
  void refuted(const Order& o, const DataWitness w[2]);
  bool replay(const Order& o, const std::vector<Value>& messages, MessageExample& ex,
              std::string* why);
  std::optional<model::TestCase> resource_test(const Order& o, const std::vector<Value>& messages,
                                               std::string* why_not);

  const model::App& app_;
  const std::vector<PortScope>& scopes_;
  const VerifyOptions& options_;
  z3::context& ctx_;
  Clock::time_point deadline_;
  DataQuery& data_;
  const model::Resource& res_;
  ResourceResult& out_;
  std::map<std::pair<size_t, size_t>, JointScope> joints_;  // by the two ports' indices
};

// The joint scope of a's and b's ports (a.port < b.port), made on first use.
JointScope& ResourceChecker::joint(const ResourceRule& a, const ResourceRule& b) {
  auto [it, fresh] = joints_.try_emplace({a.port, b.port});
  if (fresh) it->second = make_joint_scope(app_, *a.scope, *b.scope);
  return it->second;
}

// Whether o.first can deliver and then o.second be selected: one query over the joint scope, in
// which the second's guard reads what the first's delivery events leave (present, or either
// way: a fresh variable).
void ResourceChecker::decide_order(const ResourceRule& a, const ResourceRule& b, Order& o) {
  JointScope& j = joint(a, b);
  bool first_is_a = o.first == &a;
  const auto& second_names = first_is_a ? j.names_b : j.names_a;
  o.effects = delivery_effects(app_, data_, *o.first->connection, res_.ports[o.second->port],
                               o.second->scope->events, uses());
  PortScope s;
  s.port = j.scope.port;
  s.events = j.scope.events;
  s.domain = j.scope.domain;
  int fi = first_is_a ? a.index : j.first_rules + b.index;
  int si = first_is_a ? j.first_rules + b.index : a.index;
  s.rules = {j.scope.rules[static_cast<size_t>(fi)], j.scope.rules[static_cast<size_t>(si)]};
  std::map<std::string, Constraint> after;
  for (const DeliveryEffect& e : o.effects) {
    const std::string& v = second_names.at(e.event);
    if (e.must_set) {
      after[v] = Constraint::constant(true);
    } else {
      after[v] = Constraint::event_ref(v + "'");  // either way after the delivery
      s.events.push_back(v + "'");
    }
  }
  // PortSolver finds an event's variable by binary search: the primed names keep it sorted.
  std::sort(s.events.begin(), s.events.end());
  ScopedRule& second = s.rules[1];
  second.effective_guard = map_events(second.effective_guard, [&](const std::string& e) {
    auto it = after.find(e);
    return it == after.end() ? Constraint::event_ref(e) : it->second;
  });
  PortSolver solver(s, ctx_, deadline_);
  std::optional<std::vector<std::string>> state = solver.minimal_state({0, 1}, {});
  o.answer = state                                     ? Answer::Sat
             : solver.last_answer() == Answer::Unknown ? Answer::Unknown
                                                       : Answer::Unsat;
  if (o.answer == Answer::Unknown) {
    unknown("an event state that selects " + pair_name(a, b), solver.unknown_reason());
  }
  if (state) {
    for (const std::string& e : *state)
      if (e.empty() || e.back() != '\'') o.state.push_back(joint_event_text(e));
  }
}

std::string ResourceChecker::effects_text(const Order& o) const {
  std::vector<std::string> set;
  for (const DeliveryEffect& e : o.effects)
    if (e.must_set) set.push_back(e.event);
  std::string first = "after '" + o.first->connection->name + "' delivers a command that uses it";
  if (set.empty())
    return first + ", '" + o.second->connection->name + "' is not selected: `" +
           o.second->rule->effective_guard.to_string() + "` and `" +
           o.first->rule->effective_guard.to_string() + "` never hold together";
  return first + ", " + join(set) + (set.size() == 1 ? " is" : " are") + " present in " +
         res_.ports[o.second->port] + " (" +
         (set.size() == 1 ? "a delivery event" : "delivery events") + "), which keeps '" +
         o.second->connection->name + "' out";
}

void ResourceChecker::by_events(const ResourceRule& a, const ResourceRule& b, const Order& ab,
                                const Order& ba) {
  if (ab.effects.empty() && ba.effects.empty()) {
    out_.exclusive_by_events.push_back(
        pair_name(a, b) + ": `" + a.rule->effective_guard.to_string() + "` and `" +
        b.rule->effective_guard.to_string() + "` never hold together");
    return;
  }
  out_.exclusive_by_events.push_back(pair_name(a, b) + ": " + effects_text(ab) + "; " +
                                     effects_text(ba));
}

// A rule opaque for data makes the pair an error: it might deliver any command. So does a
// `when` the data encoding cannot read (the length of a string): any command might use it.
bool ResourceChecker::opaque_pair(const ResourceRule& a, const ResourceRule& b) {
  for (const ResourceRule* r : {&a, &b}) {
    std::string why = data_.opaque_reason(*r->connection), what, note;
    if (!why.empty()) {
      what = "'" + r->connection->name + "' is opaque for data (" + why + ")";
      note = "without its body arbc must assume it can deliver any command";
    } else if (res_.uses) {
      why = data_.predicate_opaque_reason(*r->connection, *res_.uses);
      what =
          "its `when` cannot be read of what '" + r->connection->name + "' delivers (" + why + ")";
      note =
          "arbc must then assume any command uses it: write the `when` with what the proof reads "
          "(docs/checks.md#message-data)";
    }
    if (why.empty()) continue;
    Finding f = base_finding(kCheckResource);
    f.rules = {a.connection->name, b.connection->name};
    f.rule_ports = {a.connection->destination, b.connection->destination};
    f.rule_locs = {a.connection->loc, b.connection->loc};
    f.message = "resource '" + res_.name + "' is not proved for " + pair_name(a, b) + ": " + what;
    f.notes.push_back({note, {}});
    out_.findings.push_back(std::move(f));
    return true;
  }
  return false;
}

// Whether one of the two never delivers a command that uses the resource (said as exclusive by
// data); else each side's witness, a message of its own (two messages: even from one source,
// two decisions may come one after the other in one event state).
bool ResourceChecker::never_uses(const ResourceRule& a, const ResourceRule& b, DataWitness w[2]) {
  const ResourceRule* sides[2] = {&a, &b};
  for (int s = 0; s < 2; ++s) {
    DataCore core;
    Answer ans = data_.ask({{sides[s]->connection, uses()}}, &w[s], &core);
    if (ans == Answer::Unknown) {
      unknown("whether '" + sides[s]->connection->name + "' can use it", data_.unknown_reason());
      return true;
    }
    if (ans == Answer::Sat) continue;
    if (data_.bounded(*sides[s]->connection, uses())) out_.list_bound = options_.list_bound;
    std::string why = "'" + sides[s]->connection->name + "' never delivers a command that uses it";
    if (!core.accept_lines[0].empty())
      why += " (" + core_lines_text(core.accept_lines[0], sides[s]->connection->name) + ")";
    out_.exclusive_by_data.push_back(pair_name(a, b) + ": " + why);
    return true;
  }
  return false;
}

void ResourceChecker::check_pair(const ResourceRule& a, const ResourceRule& b) {
  ++out_.pairs;
  Order ab{&a, &b, {}, Answer::Unsat, {}}, ba{&b, &a, {}, Answer::Unsat, {}};
  decide_order(a, b, ab);
  decide_order(b, a, ba);
  if (ab.answer == Answer::Unknown || ba.answer == Answer::Unknown) return;
  if (ab.answer == Answer::Unsat && ba.answer == Answer::Unsat) return by_events(a, b, ab, ba);
  if (opaque_pair(a, b)) return;
  DataWitness w[2];
  if (never_uses(a, b, w)) return;
  if (ab.answer == Answer::Sat) return refuted(ab, w);
  DataWitness swapped[2] = {w[1], w[0]};
  refuted(ba, swapped);
}

bool ResourceChecker::replay(const Order& o, const std::vector<Value>& messages, MessageExample& ex,
                             std::string* why) {
  const model::Connection* rules[2] = {o.first->connection, o.second->connection};
  if (!replay_accepts(data_.app(), options_.runner, {rules[0], rules[1]}, messages, {0, 1}, ex,
                      why))
    return false;
  if (!res_.uses) return true;
  for (int s = 0; s < 2; ++s) {
    const model::Port* p = app_.find_port(rules[s]->destination);
    MonitorRun run;
    std::string err;
    options_.runner->run(*rules[s], messages[static_cast<size_t>(s)], &run, &err);
    std::optional<bool> used = data_.holds(*res_.uses, run.delivered, *p->type);
    // Undecided (the run's deadline passed, or the predicate is opaque): the replay neither
    // confirms nor contradicts Z3, so the pair is unknown, not an internal disagreement.
    if (!used) {
      why->clear();
      return false;
    }
    if (!*used) {
      *why = "Z3 says '" + rules[s]->name + "' delivers a command that uses '" + res_.name +
             "', but its Lua monitor delivers " + spec_value_text(run.delivered) +
             ", which does not, for the message " +
             spec_value_text(messages[static_cast<size_t>(s)]);
      return false;
    }
  }
  return true;
}

// The counterexample as a test (verify/claim_test.h): the state before the first decision, set
// by name (a test's `set` reaches every container fed the event: where the state has an event
// in one port only, the replay decides whether the test still breaks the claim), then each
// rule's message in order, and `expect resource R;`.
std::optional<model::TestCase> ResourceChecker::resource_test(const Order& o,
                                                              const std::vector<Value>& messages,
                                                              std::string* why_not) {
  DecisionReplay d;
  d.name = "counterexample: '" + o.first->connection->name + "' then '" +
           o.second->connection->name + "' deliver commands that use " + res_.name;
  std::set<std::string> present;
  for (const std::string& e : o.state) present.insert(e.substr(0, e.find(' ')));  // "e in M.p"
  // Events present in one port's copy, where the other port reads its own copy, absent.
  std::vector<std::string> one_port;
  for (const ResourceRule* r : {o.first, o.second}) {
    const ResourceRule* other = r == o.first ? o.second : o.first;
    const std::string& here = res_.ports[r->port];
    const std::string& there = res_.ports[other->port];
    for (const std::string& e : present) {
      auto has = [&](const std::string& copy) {
        return std::find(o.state.begin(), o.state.end(), copy) != o.state.end();
      };
      const std::vector<std::string>& read = other->scope->events;
      if (has(e + " in " + here) && !has(e + " in " + there) &&
          std::find(read.begin(), read.end(), e) != read.end())
        one_port.push_back(e + " in " + here);
    }
  }
  d.state.present.assign(present.begin(), present.end());
  d.rules = {o.first->connection, o.second->connection};
  d.messages = {messages[0], messages[1]};
  d.claim = resource_claim(res_.name);
  d.message_per_rule = true;
  if (!one_port.empty())
    d.kept_because = "its state has " + join(one_port) +
                     " present, not in the other port, and a test's `set` reaches every port's "
                     "container fed the event";
  return decision_test(d, data_, options_.test_replayer, why_not);
}

// `w[0]` is the first rule's witness, `w[1]` the second's.
void ResourceChecker::refuted(const Order& o, const DataWitness w[2]) {
  const ResourceRule& a = *o.first;
  const ResourceRule& b = *o.second;
  Finding f = base_finding(kCheckResource);
  f.rules = {a.connection->name, b.connection->name};
  f.rule_ports = {a.connection->destination, b.connection->destination};
  f.rule_locs = {a.connection->loc, b.connection->loc};
  f.message = pair_name(a, b) + " can both deliver a command that uses resource '" + res_.name +
              "' (two messages, one decision after the other in one event state)";
  f.notes.push_back({"in the event state (fewest events present): present: " +
                         (o.state.empty() ? std::string("none") : join(o.state)),
                     {}});
  std::vector<Value> messages;
  for (int s = 0; s < 2; ++s) {
    MessageExample ex;
    ex.source = w[s].message_sources[0];
    ex.value = spec_value_text(w[s].messages[0], port_type_of(data_.app(), ex.source));
    messages.push_back(w[s].messages[0]);
    f.messages.push_back(ex);
    f.notes.push_back(
        {"message " + std::to_string(s + 1) + ": " + ex.source + " = " + ex.value, {}});
  }
  for (int s = 0; s < 2; ++s) {
    const ResourceRule& r = s == 0 ? a : b;
    std::string when = s == 0 ? "first" : "then, in the state the first delivery left,";
    f.notes.push_back({when + " '" + r.connection->name + "' is selected (`" +
                           r.rule->effective_guard.to_string() + "`) and delivers " +
                           spec_value_text(w[s].emitted[0]) + " to " + res_.ports[r.port],
                       r.connection->loc});
  }
  std::vector<std::string> assumed = w[0].assumed_state[0];
  assumed.insert(assumed.end(), w[1].assumed_state[0].begin(), w[1].assumed_state[0].end());
  if (!assumed.empty()) {
    f.notes.push_back({"with monitor state " + join(assumed) +
                           " (abstracted: any value earlier messages could leave), so not "
                           "replayed",
                       {}});
    f.not_replayable = "it needs monitor state that earlier messages would have to leave";
  } else if (options_.runner) {
    MessageExample ex;
    std::string why;
    if (!replay(o, messages, ex, &why)) {
      if (why.empty())
        unknown("whether the replayed commands use it",
                Clock::now() >= deadline_ ? "timeout" : "its predicate is not modelled");
      else
        out_.findings.push_back(internal_data_error("", res_.loc, why));
      return;
    }
    f.messages.back().replay = ex.replay;
    f.notes.push_back({"replayed through the Lua monitors: " + join(ex.replay, "; "), {}});
    f.replay_test = resource_test(o, messages, &f.not_replayable);
  } else {
    f.notes.push_back({"not replayed (no monitor runner)", {}});
    f.not_replayable = "it was not replayed";
  }
  f.notes.push_back(
      {"keep '" + b.connection->name + "' out after '" + a.connection->name +
           "' delivers: a delivery event of " + res_.ports[a.port] + " (`event e = " +
           res_.ports[a.port] + " : PREDICATE for D;`) with `not e` in '" + b.connection->name +
           "''s `when`, and the same the other way round (docs/language.md#delivery-events); "
           "or make one of them never deliver a command that uses it",
       {}});
  out_.findings.push_back(std::move(f));
}

}  // namespace

void run_resource_checks(const model::App& app, const std::vector<PortScope>& scopes,
                         const VerifyOptions& options, z3::context& ctx, Clock::time_point deadline,
                         DataQuery& data, VerifyReport& report) {
  for (const model::Resource& res : app.resources) {
    ResourceResult out;
    ResourceChecker(app, scopes, options, ctx, deadline, data, res, out).run();
    report.resources.push_back(std::move(out));
  }
}

}  // namespace arbc::verify
