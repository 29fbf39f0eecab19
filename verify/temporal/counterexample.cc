#include "verify/temporal/counterexample.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "core/duration_literal.h"
#include "core/join.h"
#include "verify/claim_test.h"
#include "verify/temporal/property.h"

namespace arbc::verify::temporal {
namespace {

class Builder {
 public:
  Builder(const PortShape& shape, const Unrolling& u, const z3::model& m, DataQuery& data)
      : shape_(shape), u_(u), m_(m), data_(data) {
    for (const Entry& e : shape_.entries)
      if (from_harness(e)) harness_[e.event] = false;
  }

  // Appends step k; false (and why_not) when it cannot be replayed.
  bool add(int k, const model::TemporalProperty& p) {
    lapses_before(k);
    const model::Connection& c = *shape_.connections[static_cast<size_t>(u_.connection(m_, k))];
    if (c.kind == model::ConnectionKind::Feed) {
      feed_step(k);
      return true;
    }
    return rule_step(k, c, p);
  }

  model::TestCase test;
  std::string why_not;

 private:
  // An entry the test gives with `set`/`unset`: a feed's, except the port's own delivery
  // events, which the replayed deliveries set as the runtime does.
  bool from_harness(const Entry& e) const {
    return shape_.connections[static_cast<size_t>(e.owner)]->kind == model::ConnectionKind::Feed &&
           !e.own_delivery();
  }

  // Whether the feeds' entries make `event` present in state s at time t.
  bool fed(const std::string& event, int s, Nanos t) const {
    for (size_t q = 0; q < shape_.entries.size(); ++q) {
      const Entry& e = shape_.entries[q];
      if (e.event != event || !from_harness(e)) continue;
      Unrolling::EntryValue v = u_.entry(m_, s, q);
      if (v.has && (v.forever || t < v.expiry)) return true;
    }
    return false;
  }

  void event_step(model::TestStep::Kind kind, Nanos t, const std::string& event) {
    model::TestStep s;
    s.kind = kind;
    s.t = t;
    s.event = event;
    test.steps.push_back(std::move(s));
  }

  // Feed entries that lapsed between step k-1 and step k: unset when the last one expired,
  // in time order (the harness's `set` lasts until unset).
  void lapses_before(int k) {
    Nanos t = u_.time_value(m_, k);
    std::vector<std::pair<Nanos, std::string>> lapsed;
    for (auto& [event, present] : harness_) {
      if (!present || fed(event, k, t)) continue;
      Nanos last{0};
      for (size_t q = 0; q < shape_.entries.size(); ++q) {
        const Entry& e = shape_.entries[q];
        Unrolling::EntryValue v = u_.entry(m_, k, q);
        if (e.event == event && from_harness(e) && v.has && !v.forever)
          last = std::max(last, v.expiry);
      }
      lapsed.emplace_back(last, event);
      present = false;
    }
    std::sort(lapsed.begin(), lapsed.end());
    for (const auto& [at, event] : lapsed) event_step(model::TestStep::Kind::Unset, at, event);
  }

  // A feed's step: the events whose presence it changed, set or unset by the test.
  void feed_step(int k) {
    Nanos t = u_.time_value(m_, k);
    for (auto& [event, present] : harness_) {
      bool now = fed(event, k + 1, t);
      if (now == present) continue;
      event_step(now ? model::TestStep::Kind::Set : model::TestStep::Kind::Unset, t, event);
      present = now;
    }
  }

  // What step k's delivery does to the own delivery events the rule does not decide alone: a
  // side asking that the delivered value makes each predicate true (set) or not (not set).
  std::vector<DataSide> own_delivery_sides(int k, const model::Connection& c) const {
    std::vector<DataSide> sides;
    int owner = u_.connection(m_, k);
    if (!u_.trace_step(m_, k).delivered) return sides;
    for (size_t q = 0; q < shape_.entries.size(); ++q) {
      const Entry& e = shape_.entries[q];
      if (!e.own_delivery() || !e.predicate) continue;
      const DeliveryOutcome& o = e.on_delivery[static_cast<size_t>(owner)];
      if (o.can_set + o.can_unset + o.can_keep < 2) continue;
      bool set = false;
      for (const std::string& ev : u_.trace_step(m_, k).set) set = set || ev == e.event;
      sides.push_back({&c, e.predicate, !set});
    }
    return sides;
  }

  // A witness that `c` accepts with `extra` (what its delivery must do to events), once per
  // rule and extra.
  const DataWitness* witness(const model::Connection& c, const std::vector<DataSide>& extra) {
    std::string key = c.destination + "/" + c.name;
    for (const DataSide& s : extra)
      key += "|" + std::to_string(reinterpret_cast<uintptr_t>(s.emitted_holds)) +
             (s.negate ? "-" : "+");
    auto found = witnesses_.find(key);
    if (found != witnesses_.end()) return &found->second;
    std::string opaque = data_.opaque_reason(c);
    if (!opaque.empty()) {
      why_not = "'" + c.name + "' is opaque for data (" + opaque + ")";
      return nullptr;
    }
    DataWitness w;
    std::vector<DataSide> sides{{&c, nullptr}};
    sides.insert(sides.end(), extra.begin(), extra.end());
    Answer a = data_.ask(sides, &w, nullptr);
    // No value does what the trace says (it kept an event the feed's Lua may fail to change, or
    // the predicates are not exact): any accepted message, and the replay judges the trace.
    if (a == Answer::Unsat && !extra.empty()) {
      w = DataWitness{};
      a = data_.ask({{&c, nullptr}}, &w, nullptr);
    }
    if (a != Answer::Sat) {
      why_not = a == Answer::Unsat
                    ? "'" + c.name + "' accepts no message"
                    : "no message found for '" + c.name + "' (" + data_.unknown_reason() + ")";
      return nullptr;
    }
    if (!w.assumed_state[0].empty()) {
      why_not = "'" + c.name + "' accepts only with monitor state " + join(w.assumed_state[0]);
      return nullptr;
    }
    return &witnesses_.emplace(key, std::move(w)).first->second;
  }

  // A rule's step: a message it accepts; a rejected message that changes nothing is left out.
  bool rule_step(int k, const model::Connection& c, const model::TemporalProperty& p) {
    int owner = u_.connection(m_, k);
    if (!u_.accepted(m_, k)) {
      for (size_t q = 0; q < shape_.entries.size(); ++q) {
        if (shape_.entries[q].owner == owner && u_.changes(m_, k, q)) {
          why_not = "a message '" + c.name + "' rejects but that changes its events";
          return false;
        }
      }
      return true;
    }
    const DataWitness* w = witness(c, own_delivery_sides(k, c));
    if (!w) return false;
    Nanos t = u_.time_value(m_, k);
    model::TestStep s;
    s.t = t;
    s.port = c.source;
    s.value = w->messages[0];
    if (const model::Port* port = data_.app().find_port(c.source)) s.type = port->type;
    test.steps.push_back(std::move(s));
    // The deliveries the property is about (for a property over two rules, both rules') as
    // expectations.
    bool named = c.name == p.rule || p.kind == model::TemporalProperty::Kind::Stability ||
                 (!p.other.empty() && c.name == p.other);
    if (named && u_.trace_step(m_, k).delivered) {
      model::Expectation e;
      e.port = c.destination;
      e.value = w->emitted[0];
      e.from = e.to = t;
      e.connection = c.name;  // the rule that delivered it; a `receives` ignores it
      e.text = c.destination + " receives " +
               spec_value_text(w->emitted[0], port_type_of(data_.app(), c.destination)) + " at " +
               duration_literal(t);
      test.expectations.push_back(std::move(e));
    }
    return true;
  }

  const PortShape& shape_;
  const Unrolling& u_;
  const z3::model& m_;
  DataQuery& data_;
  std::map<std::string, bool> harness_;  // per event the feeds set: present in the test's entry
  std::map<std::string, DataWitness> witnesses_;  // by rule and what its delivery must do
};

}  // namespace

std::optional<model::TestCase> counterexample_test(const PortShape& shape, const Unrolling& u,
                                                   const z3::model& m, int steps,
                                                   const model::TemporalProperty& p,
                                                   DataQuery& data, std::string* why_not) {
  Builder b(shape, u, m, data);
  b.test.name = "counterexample: " + property_words(p);
  for (int k = 0; k < steps; ++k) {
    if (!b.add(k, p)) {
      *why_not = b.why_not;
      return std::nullopt;
    }
  }
  return std::move(b.test);
}

std::string test_file_text(const model::TestCase& replay, const model::TemporalProperty& p,
                           const std::string& spec_path) {
  return counterexample_file_text(
      replay, property_words(p), spec_path,
      "// A counterexample `arbc verify` found and replayed on the runtime, kept as a regression\n"
      "// test: it expects the property itself over these inputs, so `arbc test --no-verify FILE`\n"
      "// fails on that app and passes once it is fixed. Events the app's feeds set are given\n"
      "// directly (`set`/`unset`).\n");
}

}  // namespace arbc::verify::temporal
