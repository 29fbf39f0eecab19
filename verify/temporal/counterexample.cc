#include "verify/temporal/counterexample.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "core/duration_literal.h"
#include "core/event_facts.h"
#include "core/join.h"
#include "verify/claim_test.h"
#include "verify/temporal/feed_outcomes.h"
#include "verify/temporal/property.h"

namespace arbc::verify::temporal {
namespace {

class Builder {
 public:
  Builder(const PortShape& shape, const Unrolling& u, const z3::model& m, DataQuery& data,
          int steps)
      : shape_(shape), u_(u), m_(m), data_(data), steps_(steps) {}

  // Appends the message of step k and of the steps after it that it continues (the same
  // source at the same instant, as the runtime hands one message to each connection from it);
  // the number of steps it took, 0 (and why_not) when they cannot be replayed.
  int add(int k, const model::TemporalProperty& p) {
    int end = k + 1;
    while (end < steps_ && continues(end)) ++end;
    std::vector<DataSide> sides;
    std::vector<int> accepted;  // steps whose rule accepts the message
    status_.reset();
    bool fed = false;
    for (int j = k; j < end; ++j) {
      const model::Connection& c = connection(j);
      if (model::is_delivery_feed(data_.app(), c)) {
        // Its source is an arbitrated `in` port, whose deliveries this port's trace takes as
        // given: a test cannot publish there, only through that port's rules, which the trace
        // does not choose (drt seed 38 wrote `at 0s D2.q2 <- 0;`, which `arbc test` refuses).
        why_not = "events of '" + c.name + "' come from what " + c.source +
                  " delivers, which a test input cannot give directly";
        return 0;
      }
      if (c.kind == model::ConnectionKind::Feed) {
        if (!feed_sides(j, c, sides)) return 0;
        fed = true;
      } else if (!rule_sides(j, c, sides, accepted)) {
        return 0;
      }
    }
    if (status_ && !sides.empty()) {
      why_not = "a status message of " + connection(k).source + " that must also decide events " +
                "or be accepted by a rule";
      return 0;
    }
    if (!fed && sides.empty()) return end - k;  // rejected messages that change nothing
    if (fed && sides.empty() && !status_)
      sides.push_back({&data_.pass_through(connection(k).source), nullptr});
    const DataWitness* w = status_ ? nullptr : witness(sides);
    if (!status_ && !w) return 0;
    model::TestStep s;
    s.t = u_.time_value(m_, k);
    s.port = connection(k).source;
    s.value = status_ ? *status_ : w->messages[0];
    if (const model::Port* port = data_.app().find_port(s.port)) s.type = port->type;
    test.steps.push_back(std::move(s));
    for (int j : accepted)
      if (!expect_delivery(j, p, *w)) return 0;
    return end - k;
  }

  model::TestCase test;
  std::string why_not;

 private:
  const model::Connection& connection(int k) const {
    return *shape_.connections[static_cast<size_t>(u_.connection(m_, k))];
  }

  // Whether step k is handled by a connection of step k-1's source after it, at its instant.
  bool continues(int k) const {
    return connection(k).source == connection(k - 1).source &&
           u_.connection(m_, k) > u_.connection(m_, k - 1) &&
           u_.time_value(m_, k) == u_.time_value(m_, k - 1);
  }

  // A feed's step: a message of its source that sets the events the step sets and removes
  // those it removes (a derived event kept with `for D`: its predicate is false), so the
  // runtime's own feed makes the container what the trace says, never the test directly.
  bool feed_sides(int k, const model::Connection& feed, std::vector<DataSide>& sides) {
    TraceStep step = u_.trace_step(m_, k);
    auto in = [](const std::vector<std::string>& v, const std::string& e) {
      return std::find(v.begin(), v.end(), e) != v.end();
    };
    const model::Connection& message = data_.pass_through(feed.source);
    ValueList flags;
    for (const Entry& e : shape_.entries) {
      if (shape_.connections[static_cast<size_t>(e.owner)] != &feed) continue;
      const model::Event* event = data_.app().find_event(e.event);
      bool set = in(step.set, e.event), unset = in(step.unset, e.event);
      if (event && event->predicate) {
        if (set || unset || (e.by_message && e.lifetime))
          sides.push_back({&message, &*event->predicate, !set});
      } else if (event && !event->source.empty()) {
        if (set) flags.push_back(Value(status_flag(*event)));
        status_ = Value(flags);
      } else {
        why_not = "'" + e.event + "' is not set by a message of " + feed.source;
        return false;
      }
    }
    return true;
  }

  // A rule's step: a message it accepts, with what its delivery does to the port's own delivery
  // events; a rejected message must change nothing.
  bool rule_sides(int k, const model::Connection& c, std::vector<DataSide>& sides,
                  std::vector<int>& accepted) {
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
    std::string opaque = data_.opaque_reason(c);
    if (!opaque.empty()) {
      why_not = "'" + c.name + "' is opaque for data (" + opaque + ")";
      return false;
    }
    rule_side_.emplace_back(k, sides.size());
    sides.push_back({&c, nullptr});
    std::vector<DataSide> own = own_delivery_sides(k, c);
    sides.insert(sides.end(), own.begin(), own.end());
    accepted.push_back(k);
    return true;
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

  // A message for `sides` (the accepting rules first, what their deliveries and the feeds must
  // do after them), asked once per question. When no message does what the deliveries' own
  // events say (a predicate that is not exact), any message the rules accept with the feeds'
  // outcomes, and the replay judges the trace; no message for a feed's outcomes: no replay.
  const DataWitness* witness(const std::vector<DataSide>& sides) {
    std::string key;
    for (const DataSide& s : sides)
      key += std::to_string(reinterpret_cast<uintptr_t>(s.connection)) + "/" +
             std::to_string(reinterpret_cast<uintptr_t>(s.emitted_holds)) + (s.negate ? "-" : "+") +
             "|";
    auto found = witnesses_.find(key);
    if (found != witnesses_.end()) return &found->second;
    DataWitness w;
    Answer a = data_.ask(sides, &w, nullptr);
    if (a == Answer::Unsat) {
      std::vector<DataSide> loose;
      for (const DataSide& s : sides)
        if (s.connection->kind != model::ConnectionKind::Rule || !s.emitted_holds ||
            s.connection == &data_.pass_through(s.connection->source))
          loose.push_back(s);
      if (loose.size() < sides.size()) {
        w = DataWitness{};
        a = data_.ask(loose, &w, nullptr);
      }
    }
    if (a != Answer::Sat) {
      // One rule alone: say which; else what the message had to do.
      const model::Connection& first = *sides[0].connection;
      bool one_rule = &first != &data_.pass_through(first.source) &&
                      std::all_of(sides.begin(), sides.end(),
                                  [&](const DataSide& s) { return s.connection == &first; });
      std::string what = one_rule ? "'" + first.name + "'" : "a message of " + first.source;
      why_not = a == Answer::Unsat
                    ? (one_rule ? what + " accepts no message"
                                : "no message of " + first.source + " does what the trace says")
                    : "no message found for " + what + " (" + data_.unknown_reason() + ")";
      return nullptr;
    }
    for (size_t i = 0; i < w.assumed_state.size(); ++i) {
      if (w.assumed_state[i].empty()) continue;
      why_not = "'" + sides[i].connection->name + "' accepts only with monitor state " +
                join(w.assumed_state[i]);
      return nullptr;
    }
    return &witnesses_.emplace(key, std::move(w)).first->second;
  }

  // The delivery of step k as an expectation when the property is about its rule (for a
  // property over two rules, both rules'). False (why_not set) when the witness has no value
  // for that rule's delivery: the test cannot say what the port receives. (It read past
  // `w.emitted` there, and `arbc verify` crashed now and then: drt seed 19001, spec 224.)
  bool expect_delivery(int k, const model::TemporalProperty& p, const DataWitness& w) {
    const model::Connection& c = connection(k);
    size_t side = 0;
    for (const auto& [step, at] : rule_side_)
      if (step == k) side = at;
    bool named = c.name == p.rule || p.kind == model::TemporalProperty::Kind::Stability ||
                 (!p.other.empty() && c.name == p.other);
    if (!named || !u_.trace_step(m_, k).delivered) return true;
    if (side >= w.emitted.size()) {
      why_not = "the witness of the messages has no value for what '" + c.name + "' delivers";
      return false;
    }
    Nanos t = u_.time_value(m_, k);
    model::Expectation e;
    e.port = c.destination;
    e.value = w.emitted[side];
    e.from = e.to = t;
    e.connection = c.name;  // the rule that delivered it; a `receives` ignores it
    e.text = c.destination + " receives " +
             spec_value_text(w.emitted[side], port_type_of(data_.app(), c.destination)) + " at " +
             duration_literal(t);
    test.expectations.push_back(std::move(e));
    return true;
  }

  const PortShape& shape_;
  const Unrolling& u_;
  const z3::model& m_;
  DataQuery& data_;
  int steps_;
  std::optional<Value> status_;  // the status list of the message being built, if it is one
  std::vector<std::pair<int, size_t>> rule_side_;  // per accepting rule step: its side's index
  std::map<std::string, DataWitness> witnesses_;   // by question
};

}  // namespace

std::optional<model::TestCase> counterexample_test(const PortShape& shape, const Unrolling& u,
                                                   const z3::model& m, int steps,
                                                   const model::TemporalProperty& p,
                                                   DataQuery& data, std::string* why_not) {
  Builder b(shape, u, m, data, steps);
  b.test.name = "counterexample: " + property_words(p);
  for (int k = 0; k < steps;) {
    int taken = b.add(k, p);
    if (taken == 0) {
      *why_not = b.why_not;
      return std::nullopt;
    }
    k += taken;
  }
  return std::move(b.test);
}

std::string test_file_text(const model::TestCase& replay, const model::TemporalProperty& p,
                           const std::string& spec_path) {
  return counterexample_file_text(
      replay, property_words(p), spec_path,
      "// A counterexample `arbc verify` found and replayed on the runtime, kept as a regression\n"
      "// test: it expects the property itself over these inputs, so `arbc test --no-verify FILE`\n"
      "// fails on that app and passes once it is fixed. The app's feeds set their events from\n"
      "// the messages of their sources, as they would in a run.\n");
}

}  // namespace arbc::verify::temporal
