// The claims `arbc verify` proves about single decisions, checked on a run's trace (issue 39):
//   - exclusivity of each arbitrated port (not `by priority`): no message is delivered by two
//     rules of the port (rules of one source read the same messages: the n-th decision record
//     of each is about the n-th message), and no rule delivers in an event state where a rule of
//     another source of the port is selected too (its decision guard holds: the proof says no
//     state has both; core/effective_guard.h);
//   - each `assert PORT: RULE -> EXPR` over events: EXPR holds in the port's state whenever RULE
//     delivers.
// The state check needs the whole state: on a mediator that starts with events unknown until
// their feeds speak (runtime.h, unknown_until_fed) an unknown event reads as absent here, so
// that check is left out there (`states_known` false); the same-message check stays.
// A rule with `then set` / `then unset` changes the events as it delivers: a rule of another
// source is then "selected too" only if it is selected both in the state the delivery was
// decided in and in the state it leaves (verify/delivery_order.h: whichever delivers first keeps
// the other out).
// `by priority` ports are left out: a higher rule may deliver right after a lower one in one
// state by design (docs/design.md#priorities-and-holds), and their hold is the runtime's own.
// Asserts over delivered data are not checked yet (the trace does not carry the value to it).
#pragma once

#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/app_model.h"
#include "core/instant.h"
#include "runtime/name_map.h"
#include "runtime/trace_format.h"

namespace arbc {

class DecisionWatch {
 public:
  // `here(port)`: the port is mediated in this process. `broken(claim, t, what)` reports a
  // breach (ClaimWatch reports each claim once).
  using Report = std::function<void(const std::string&, Nanos, const std::string&)>;
  DecisionWatch(const model::App& app, const std::function<bool(const std::string&)>& here,
                bool states_known, Report broken);

  // How many claims it watches, and their texts (each port's exclusivity, then the asserts).
  size_t size() const { return ports_.size() + asserts_.size(); }
  std::vector<std::string> claims() const;
  // A port's exclusivity as breaches name it (an assert: model::assertion_text).
  static std::string exclusivity_claim(const model::ArbitratedPort& p);
  // A port's events as breaches list them: "a, b", or "none".
  static std::string events_present(const std::set<std::string>& state);
  // A Deliver or Drop record of a rule connection of a watched port, with the port's state.
  void decision(const TraceLine& r, const std::set<std::string>& state);
  // The same, for the rule numbered `rule` (rule_of(r.connection), found once by the caller);
  // `version`: the TraceContainer::version() `state` came with (0: unknown). What reads the
  // state alone is judged once per rule and state: the verdict is the same, and a breach was
  // reported the first time (each claim is reported once).
  void decision(size_t rule, const TraceLine& r, const std::set<std::string>& state,
                uint64_t version);
  // The number of the rule named `name`; NameIndex::npos when it is not watched.
  size_t rule_of(std::string_view name) const {
    auto it = rule_index_.find(name);
    return it == rule_index_.end() ? NameIndex::npos : it->second;
  }
  void decision(const TraceRecord& r, const std::set<std::string>& state) {
    decision(trace_line_of(r), state);
  }

 private:
  struct Rule {
    std::string name, port, source;
    Constraint guard;        // the decision guard: what the runtime evaluates at its decision
    uint64_t decided = 0;    // its Deliver and Drop records so far
    bool exclusive = false;  // its port's exclusivity is watched (ports_)
    const std::set<std::string>* judged = nullptr;  // the state it was last judged in, and
    uint64_t judged_version = 0;                    // its version (decision())
    // Message numbers delivered, not yet past every sibling of the same source (only those read
    // it: empty without them).
    std::set<uint64_t> delivered;
    std::vector<size_t> same_source;   // other rules of the port reading the same source
    std::vector<size_t> other_source;  // other rules of the port reading other sources
    std::vector<size_t> asserts;       // into asserts_
    // `then set` / `then unset`: what its delivery does to the port's events before the next
    // decision (model::Connection::delivery_sets, delivery_unsets).
    std::vector<std::string> delivery_sets, delivery_unsets;
  };
  struct Assert {
    const model::Assertion* a;
    std::string text;
  };
  // `judged`: c was judged in this state already (decision()): only the same-message check.
  void delivered(Rule& c, uint64_t n, Nanos t, const std::set<std::string>& state, bool judged);
  std::vector<Rule> rules_;
  NameMap<size_t> rule_index_;                               // rule name -> rules_
  std::unordered_map<std::string, std::string> port_claim_;  // port -> its claim's text
  std::set<std::string> ports_;
  std::vector<Assert> asserts_;
  bool states_known_;
  Report broken_;
};

}  // namespace arbc
