// N steps of one arbitrated port over the runtime's instants, as Z3 terms: the encoding of
// docs/design.md#properties-over-time. Step k is one message that one connection into the port
// (a rule or a feed) handles at time t_k; the container holds one entry per (event, owner) with
// its expiry; message data is abstract, so which connection runs, whether its `accept` accepts,
// and the events it may (not must) set or unset are free. Properties over time add their own
// formula over `delivers` and `time` and ask the solver.
#pragma once

#include <z3++.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "verify/report.h"

namespace arbc::verify {
class DataQuery;
}

namespace arbc::verify::temporal {

// What one delivery can do to an own delivery entry (verify/temporal/own_delivery.h): set it
// (the predicate holds on the value), unset it (it does not, and the event has no `for`), or
// keep it as it was (the predicate is false with `for`, or the feed's Lua fails).
struct DeliveryOutcome {
  bool can_set = true, can_unset = true, can_keep = true;
};

// One entry of the container: `event` as set by connection `owner`.
struct Entry {
  std::string event;
  int owner = 0;  // index into PortSteps::connections
  // Set by the runtime each time the owner delivers (its `by priority` activity event, or a
  // `then set`), after the decision; removed only by a delivery of a rule in `unset_by`
  // (`then unset`, indices into PortSteps::connections).
  bool activity = false;
  std::vector<int> unset_by;
  std::optional<Nanos> lifetime;  // fixed lifetime; none with !free_lifetime: no expiry
  bool free_lifetime = false;     // `set e for D` in rule code: D is not in the model
  // A feed's derived event whose predicate is the constant true or false (PortShape::faithful).
  std::optional<bool> constant_predicate;
  // A delivery event of the port read by the port itself (verify/temporal/own_delivery.h): per
  // connection (as PortShape::connections), what its delivery can do; empty for any other
  // entry. The owner is the event's feed, which takes no step of its own.
  std::vector<DeliveryOutcome> on_delivery;
  // The event's predicate: over the delivered value (own delivery), or over its source's
  // message (a derived event of a feed; verify/temporal/feed_outcomes.h).
  const model::BodyExpr* predicate = nullptr;
  // A feed entry each message of its source decides (verify/temporal/feed_outcomes.h): set when
  // the predicate holds (a status flag: the flag is in the list), else removed, or kept as it
  // was for a derived event with `for D`. False: the feed sets and removes it freely.
  bool by_message = false;
  bool own_delivery() const { return !on_delivery.empty(); }
};

// What the unrolling needs of the port, read from the model once.
struct PortShape {
  std::string port;
  std::vector<const model::Connection*> connections;  // rules and feeds into the port
  std::vector<Entry> entries;
  std::vector<std::string> events;  // every event in the container or a constraint, sorted
  // The environment assumptions about this port (verify/temporal/assumption.h), each with the
  // indices of its rules among `connections` (until: -1 when it has none).
  struct Assumed {
    model::Assumption assumption;
    int after = -1, until = -1;
  };
  std::vector<Assumed> assumptions;
  // Runs as a replay makes them (verify/temporal/faithful.cc), asked again when a
  // counterexample of the free model does not replay: one message of a source reaches every
  // connection from it into the port, one after the other at one instant and in model order,
  // where the free model lets each take messages of its own; a rule that accepts every message
  // accepts it; a derived event with a constant predicate follows it. Sound proofs never use
  // it: the runtime can interleave more (a module that publishes while it takes a delivery).
  bool faithful = false;
  // A combination of own delivery events that no delivery of `rule` gives: those `sets` says
  // set, the others not (verify/temporal/own_delivery.cc).
  // With `feed`, `rule` is a feed and the combination is one that no message of its source
  // gives (verify/temporal/feed_outcomes.h): excluded at each step the feed runs.
  struct ExcludedOutcome {
    int rule = -1;
    std::vector<std::pair<size_t, bool>> sets;  // entry index, set by the delivery
    bool feed = false;
  };
  std::vector<ExcludedOutcome> excluded_outcomes;
  // Presence of a feed's entries without a lifetime that no state has: the last message of
  // the source set exactly those whose predicate held, and no message any none (k-induction's
  // any state; verify/temporal/feed_outcomes.h).
  std::vector<ExcludedOutcome> excluded_at_start;
};

// The port's shape; nullopt and *err when `port` is not an arbitrated port of `app`. `data`
// (may be null) tells what the port's deliveries do to its own delivery events.
std::optional<PortShape> port_shape(const model::App& app, const std::string& port,
                                    std::string* err, DataQuery* data = nullptr);

// Adds to `shape` the app's assumptions about its port; false and *err when one names a rule
// the port does not have (an app.json written by hand: bad input). verify/temporal/assumption.cc
bool add_port_assumptions(const model::App& app, PortShape& shape, std::string* err);

// The index of rule `rule` among the shape's connections; -1 when the port has no such rule.
int rule_index(const PortShape& shape, const std::string& rule);
// `d` (a lifetime, hold, throttle, window or rate period) as a Z3 integer of nanoseconds, the
// unit every time of the unrolling is counted in: the runtime's instants are whole nanoseconds
// compared exactly (core/instant.h), so a model over integers is a run the runtime can have,
// and a proof over them covers every pair of its instants (a hold of 1 s lapses at exactly
// 1000000000, not a hair later). Times were reals once: a violation strictly between two
// nanoseconds then needed a second, mixed integer-real query to move onto the runtime's grid,
// which Z3 answered slowly or not at all with durations like 0.999999999 s (--temporal-bound 6
// on tests/verify/temporal_ns_slow.spec ran into --timeout). Every constraint on times is a
// difference of two times against such a constant: integer difference logic.
z3::expr nanos_term(z3::context& ctx, Nanos d);

// Whether some connection into the port can set `event` (else it is never present there).
bool sets_into(const PortShape& shape, const std::string& event);

class Unrolling {
 public:
  // Where the steps start: the empty container at time 0 (bounded model checking), or any
  // state at all (the step case of k-induction, verify/temporal/induction.h): free entries,
  // free times of each rule's last delivery, free monitor states.
  enum class Start { Empty, AnyState };
  // Adds to `solver` the constraints of `steps` steps of the port from the empty container.
  Unrolling(const PortShape& shape, int steps, z3::context& ctx, z3::solver& solver,
            Start start = Start::Empty);

  // Adds one more step (incremental BMC: the steps so far stay in the solver, and a property
  // asks about the first steps() of them inside a push/pop).
  void extend() { add_step(steps()); }
  int steps() const { return static_cast<int>(t_.size()); }
  bool from_any_state() const { return start_ == Start::AnyState; }

  // Connection `c` delivers at step k.
  z3::expr delivers(int c, int k) const { return del_[k][c]; }
  z3::expr time(int k) const { return t_[k]; }
  // Connection `c` runs step k; step k's `accept` accepted (verify/temporal/rates.h reads them).
  z3::expr runs(int c, int k) const { return run_[k] == c; }
  z3::expr accepts(int k) const { return acc_[k]; }
  // `event` is present at step k's decision (the state its connection's constraint reads).
  z3::expr present_at_decision(const std::string& event, int k) const {
    return present(event, k, t_[k]);
  }
  // `event` becomes present at step k: absent just before it, present just after it (at t_k).
  z3::expr becomes_present(const std::string& event, int k) const;
  // Whether the monitor "armed by a delivery of `on`, disarmed by one of `off`" (-1: never
  // disarmed) is armed before step k: false at an empty start, a free Boolean (one per pair,
  // shared by every formula that asks) at any state.
  z3::expr armed_before(int on, int off, int k) const;
  // Whether rule c delivered before step 1, and when (free at any state; false at an empty start).
  z3::expr delivered_before_start(int c) const;
  z3::expr last_delivery_before_start(int c) const;
  // Step k's trace line in model `m`.
  TraceStep trace_step(const z3::model& m, int k) const;

  // Values in model `m`: step k's time (kNever beyond 64 bits), the index of its connection,
  // whether it accepted.
  Nanos time_value(const z3::model& m, int k) const;
  int connection(const z3::model& m, int k) const;
  bool accepted(const z3::model& m, int k) const;
  // Entry q in state s (0: before step 1, k+1: after step k) in model `m`.
  struct EntryValue {
    bool has = false, forever = false;
    Nanos expiry{0};
  };
  EntryValue entry(const z3::model& m, int state, size_t q) const;
  // Whether step k set or removed entry q.
  bool changes(const z3::model& m, int k, size_t q) const;

 private:
  z3::expr present(const std::string& event, int state, const z3::expr& at) const;
  z3::expr guard(const Constraint& c, int k) const;
  void add_step(int k);
  void add_entry_step(size_t q, int k);
  void add_activity_step(size_t q, int k);
  void add_entry_update(size_t q, int k);       // state k+1 of entry q from its set/unset
  void add_own_delivery_step(size_t q, int k);  // own_delivery.cc
  void add_excluded_outcomes(int k);            // PortShape::excluded_outcomes at step k
  void constrain_own_deliveries_at_start();     // what any state says of them (own_delivery.cc)
  // The place of connection c's last delivery before step 1 among the others' (any state).
  z3::expr order_before_start(int c) const;
  bool has_own_deliveries() const;
  void start_state();                  // the state before step 1 (unrolling.cc)
  void add_any_start_entry(size_t q);  // one entry of any state (induction.cc)
  void constrain_any_start();          // what any state says of times before t_1 (induction.cc)
  void add_assumptions(int k);         // the environment at step k (assumption.cc)
  void add_faithful(int k);            // PortShape::faithful's constraints at step k (faithful.cc)
  void constrain_feeds_at_start();     // PortShape::excluded_at_start (feed_outcomes.cc)

  const PortShape& shape_;
  z3::context& ctx_;
  z3::solver& solver_;
  Start start_;
  std::vector<z3::expr> t_, run_, acc_;  // per step: time, connection index, accepted
  // Per state s (0: before step 1, k+1: after step k), per entry q.
  std::vector<std::vector<z3::expr>> has_, forever_, expiry_;
  std::vector<std::vector<z3::expr>> set_, unset_;  // per step, per entry: the step's choice
  std::vector<std::vector<z3::expr>> del_;          // per step, per connection
  // armed_before's terms per (on, off), per step (k: before step k), built as steps are asked.
  mutable std::map<std::pair<int, int>, std::vector<z3::expr>> armed_;
};

}  // namespace arbc::verify::temporal
