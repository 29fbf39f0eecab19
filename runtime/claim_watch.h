// What a run checks of what `arbc verify` proved and assumed (issue 39): fed every trace record
// as the runtime makes it, it watches
//   - the claims about single decisions: each port's exclusivity and its asserts over events
//     (runtime/decision_watch.h);
//   - each property over time of the app (runtime/property_watch.h): a declared property is a
//     claim (build refuses one the proof refutes), so a breach means the run left what was
//     proved;
//   - the claims about delivered values: asserts over `emitted` and resources
//     (runtime/delivery_watch.h), once load_claims() has read the claims script;
//   - the assumptions the proofs rest on, at every decision of a rule, in the state of the
//     rule's port: `exclusive` groups, `invariant`s (in the ports whose containers some of their
//     events are fed into, as the proof of that port reads them: an event not fed there may be
//     anything), environment assumptions (`assume ...`,
//     also each time its event is reported into the port),
//     and source rates (`given M.p every D`: the source published at least every D from the
//     start).
// Each claim or assumption is reported once, at the first instant a run breaks it: from there
// on the proof no longer covers the run.
// Only the ports this process mediates are watched: decisions are made where a port is
// mediated, so a process that mediates nothing (the world of a split run) watches nothing, and
// a rate is watched where a mediated port reads its source.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/app_model.h"
#include "core/instant.h"
#include "runtime/data_claims.h"
#include "runtime/decision_watch.h"
#include "runtime/delivery_watch.h"
#include "runtime/name_map.h"
#include "runtime/property_watch.h"
#include "runtime/trace.h"
#include "runtime/trace_container.h"
#include "runtime/trace_format.h"
#include "runtime/trace_record.h"
#include "runtime/transport.h"

namespace arbc {

struct ClaimViolation {
  Nanos t{0};
  std::string claim;  // as the spec writes it: "never two take within 1s", "exclusive { a, b }"
  std::string what;   // what the run did
  bool assumption = false;  // an assumption broke (not a claim)
};

class ClaimWatch {
 public:
  // Where the run happens, as far as the checks care.
  struct Scope {
    // The modules whose input ports this process mediates; those whose plugins run here
    // (runtime.h). A source hosted elsewhere starts when it first speaks.
    ModuleSet mediated = ModuleSet::everything(), hosted = ModuleSet::everything();
    // No event starts unknown (runtime.h, unknown_until_fed; decision_watch.h).
    bool states_known = true;
    // An `arbc test`: each source publishes what the test says, so a rate is judged only
    // between its first and its last message (the test is a window of the world, not all of it).
    bool test = false;
  };
  explicit ClaimWatch(const model::App& app) : ClaimWatch(app, Scope{}) {}
  ClaimWatch(const model::App& app, const Scope& scope);

  // Reads the app directory's claims script (App::claims_script), so that asserts over data
  // and resources with `when` are watched too; false (and *err) when it does not load.
  bool load_claims(const std::string& app_dir, std::string* err);
  // Whether the app states anything to watch (a run without claims pays nothing).
  bool empty() const;
  // How many claims and assumptions it watches, and what each is, as a violation names it
  // (an assumption with "assumption " before it).
  size_t size() const;
  std::vector<std::string> watched() const;
  // The `invariant`s and `exclusive` groups no run can watch, each with why: no port of the app
  // is fed their events (no rule or assert reads them), so no container ever holds them and no
  // proof rests on them. A run says so rather than count them kept.
  const std::vector<std::string>& unwatched() const { return unwatched_; }
  // The run's time starts at `t` (after a transport's wait for peers): rates count from there.
  void start(Nanos t);
  void observe(const TraceLine& r);
  void observe(const TraceRecord& r) { observe(trace_line_of(r)); }
  // observe(r), and a breach line in `trace` for each claim r showed broken (Trace::Watch).
  void watch(const TraceLine& r, Trace& trace);
  // The run ended at `end` (response windows and rates up to there are judged); once: a second
  // call changes nothing. With `trace`, a breach line for each claim only the end showed broken.
  void finish(Nanos end, Trace* trace = nullptr);
  // Its history, for a mediator's memory (runtime/mediator_memory.h, MemoryHooks): what the
  // properties and assumptions remember of the run, and which claims it found broken (a run
  // started again does not judge those again: the proof stopped covering the run there).
  nlohmann::json save() const;
  // Takes a save() of a watch of the same app; false (with *error) when `saved` is not one.
  bool load(const nlohmann::json& saved, std::string* error);
  // Applies what load took, its instants moved by `shift` into this run's time.
  void resume(Nanos shift);
  // The first violation of each claim and assumption, in the order they happened.
  const std::vector<ClaimViolation>& violations() const { return violations_; }

 private:
  struct Assumed {
    const model::Assumption* a;
    bool armed = false;
    std::optional<Nanos> last_after;
  };
  // An invariant watched in a port: the events of it that are fed into the port's container
  // (the others are never present there, and the port's proof takes them as free).
  struct Guard {
    const model::Invariant* inv;
    std::vector<std::string> unfed;
  };
  struct Rate {
    const model::SourceRate* r;
    Nanos last{0};        // the start counts (start()): `given` says "from the start"
    bool broken = false;  // reported: no longer judged (a run breaks a claim once)
    // A source in another process: its own start is its first message (a mediator started
    // before the programs it mediates is not owed their messages while they start up); one
    // that never speaks is reported at the end.
    bool awaiting_first = false;
    bool window = false;  // Scope::test: not owed before the first message nor after the last
  };
  // What a port mediated here has watched in it, found by its number (port_index_): a record's
  // port or rule is looked up once, and the checks then read these lists.
  struct PortSlot {
    // Its container; null for a rule's port that is not arbitrated until the rule first
    // decides (its events are not watched before).
    TraceContainer* box = nullptr;
    std::vector<Guard> guards;       // the invariants watched there
    std::vector<size_t> properties;  // into properties_: its own
    std::vector<size_t> assumed;     // into assumed_: the assumptions over its events
    // The state the groups and guards were last judged in (TraceContainer::version()): they
    // read it alone, so a port that decides again in it has the same verdict, reported once.
    uint64_t judged_version = 0;
  };
  struct RuleSlot {
    size_t port;      // into slots_: the port it delivers into
    size_t decision;  // DecisionWatch::rule_of it (NameIndex::npos: none)
  };

  void number_names(const model::App& app, const std::function<bool(const std::string&)>& here);
  void assumptions_over_events(const model::App& app, const std::set<std::string>& mediated);
  void published(const TraceLine& r);
  PortSlot* event_record(const TraceLine& r);
  PortSlot* decided(const TraceLine& r);
  void decision(const PortSlot& slot, const std::string& port, Nanos t,
                const std::set<std::string>& state);
  void assumption(Assumed& s, const std::string& port, const TraceLine& r,
                  const std::set<std::string>& state);
  void reported(Assumed& s, const TraceLine& r);
  // The assumed event present in `port` at `t`: a breach unless the assumption allows it.
  void present(Assumed& s, std::string_view port, Nanos t, const std::string& how);
  void rate_gaps(Nanos t);
  void rates_changed();
  void judge_end(Nanos end);
  void breach_lines(size_t from, Nanos t, Trace& trace) const;
  void rate_broken(Rate& rate, Nanos deadline, Nanos t);
  void property_breached(size_t i);
  void delivered(const TraceLine& r, const std::string& port);
  void violated(const std::string& claim, Nanos t, std::string what, bool assumption);

  const model::App& app_;
  std::optional<DecisionWatch> decisions_;    // exclusivity and asserts at each decision
  std::unique_ptr<DataClaims> data_claims_;   // load_claims()'s
  std::unique_ptr<DeliveryWatch> delivered_;  // asserts over data, resources
  bool decides_ = false;                      // some arbitrated port is mediated here
  std::vector<std::string> groups_watched_, invariants_watched_;  // here, as watched() names them
  std::vector<std::string> unwatched_;
  std::vector<std::unique_ptr<PropertyWatch>> properties_;
  std::vector<std::string> property_text_;
  std::vector<bool> property_broken_;  // reported: that property is no longer observed
  std::vector<Assumed> assumed_;
  std::vector<Rate> rates_;
  Nanos next_gap_ = kNever;  // no rate is judged broken at or before it (rates_changed())
  std::unordered_map<std::string, TraceContainer> boxes_;  // arbitrated port -> its container
  // Looked up on every record (runtime/name_map.h): ports, rules and sources by number.
  NameIndex port_index_, rule_index_, source_index_;
  std::vector<PortSlot> slots_;                       // by port_index_
  std::vector<RuleSlot> rules_;                       // by rule_index_
  std::vector<std::vector<size_t>> rates_of_source_;  // by source_index_: into rates_
  std::set<std::string> reported_;
  std::vector<ClaimViolation> violations_;
  nlohmann::json loaded_;  // load()'s, until resume()
  Nanos start_{0};
  bool finished_ = false;
};

}  // namespace arbc
