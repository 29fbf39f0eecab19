#include "runtime/decision_watch.h"

#include <algorithm>
#include <optional>

#include "core/constraint.h"
#include "core/duration_literal.h"
#include "core/effective_guard.h"
#include "core/join.h"

namespace arbc {

std::string DecisionWatch::events_present(const std::set<std::string>& state) {
  return state.empty() ? "none" : join(state);
}

DecisionWatch::DecisionWatch(const model::App& app,
                             const std::function<bool(const std::string&)>& here, bool states_known,
                             Report broken)
    : states_known_(states_known), broken_(std::move(broken)) {
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    if (!here(p.port)) continue;
    std::vector<const model::Connection*> into = app.connections_into(p.port);
    size_t first = rules_.size();
    for (const model::Connection* c : into) {
      if (c->kind != model::ConnectionKind::Rule) continue;
      rule_index_[c->name] = rules_.size();
      Rule rule;
      rule.name = c->name, rule.port = p.port, rule.source = c->source;
      rule.guard = model::decision_guard(into, *c);
      rule.delivery_sets = c->delivery_sets, rule.delivery_unsets = c->delivery_unsets;
      rules_.push_back(std::move(rule));
    }
    for (const model::Assertion& a : p.asserts) {
      auto it = rule_index_.find(a.rule);
      if (a.emitted || it == rule_index_.end()) continue;  // data asserts: delivery_watch.h
      rules_[it->second].asserts.push_back(asserts_.size());
      asserts_.push_back({&a, model::assertion_text(p.port, a)});
    }
    if (p.by_priority || rules_.size() - first < 2) continue;
    ports_.insert(p.port);
    port_claim_[p.port] = exclusivity_claim(p);
    for (size_t i = first; i < rules_.size(); ++i) rules_[i].exclusive = true;
    for (size_t i = first; i < rules_.size(); ++i)
      for (size_t j = first; j < rules_.size(); ++j)
        if (i != j)
          (rules_[i].source == rules_[j].source ? rules_[i].same_source : rules_[i].other_source)
              .push_back(j);
  }
}

std::vector<std::string> DecisionWatch::claims() const {
  std::vector<std::string> out;
  for (const std::string& port : ports_) out.push_back(port_claim_.at(port));
  for (const Assert& a : asserts_) out.push_back(a.text);
  return out;
}

std::string DecisionWatch::exclusivity_claim(const model::ArbitratedPort& p) {
  return p.port + ": rules " + join(p.rules, ", ") + " are never selected together";
}

void DecisionWatch::decision(const TraceLine& r, const std::set<std::string>& state) {
  size_t rule = rule_of(r.connection);
  if (rule != NameIndex::npos) decision(rule, r, state, 0);
}

void DecisionWatch::decision(size_t rule, const TraceLine& r, const std::set<std::string>& state,
                             uint64_t version) {
  Rule& c = rules_[rule];
  uint64_t n = ++c.decided;  // the n-th message of c's source since the start
  if (r.kind == TraceKind::Deliver) {
    bool judged = version != 0 && c.judged == &state && c.judged_version == version;
    c.judged = &state, c.judged_version = version;
    if (!judged || c.exclusive) delivered(c, n, r.t, state, judged);
  }
  if (c.same_source.empty()) return;
  // A message number no sibling of the same source can still decide is not needed any more.
  uint64_t oldest = n;
  for (size_t j : c.same_source) oldest = std::min(oldest, rules_[j].decided);
  c.delivered.erase(c.delivered.begin(), c.delivered.lower_bound(oldest));
}

void DecisionWatch::delivered(Rule& c, uint64_t n, Nanos t, const std::set<std::string>& state,
                              bool judged) {
  for (size_t k : c.asserts) {
    const Assert& a = asserts_[k];
    if (!judged && !evaluate(a.a->property, state))
      broken_(a.text, t,
              "'" + c.name + "' delivered at " + duration_literal(t) + " with " +
                  a.a->property.to_string() + " false in " + c.port +
                  " (events present: " + events_present(state) + ")");
  }
  if (!c.exclusive) return;
  for (size_t j : c.same_source) {
    const Rule& d = rules_[j];
    if (d.decided >= n && d.delivered.count(n))
      broken_(port_claim_[c.port], t,
              "one message from " + c.source + " delivered by both '" + d.name + "' and '" +
                  c.name + "' at " + duration_literal(t));
  }
  if (!c.same_source.empty()) c.delivered.insert(n);
  if (!states_known_ || judged) return;
  // The state the delivery leaves; copied only for a rule whose delivery changes it.
  std::optional<std::set<std::string>> after;
  if (!c.delivery_sets.empty() || !c.delivery_unsets.empty()) {
    after = state;
    for (const std::string& e : c.delivery_unsets) after->erase(e);
    for (const std::string& e : c.delivery_sets) after->insert(e);  // a set wins, as it runs last
  }
  for (size_t j : c.other_source) {
    const Rule& d = rules_[j];
    if (evaluate(d.guard, state) && (!after || evaluate(d.guard, *after)))
      broken_(port_claim_[c.port], t,
              "'" + c.name + "' delivered at " + duration_literal(t) + " in a state where '" +
                  d.name + "' is selected too (events present: " + events_present(state) + ")");
  }
}

}  // namespace arbc
