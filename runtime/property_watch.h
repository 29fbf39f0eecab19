// What a property over time (core/app_model.h, TemporalProperty;
// docs/language.md#properties-over-time) means for one run, judged on the trace records in the
// order the runtime made them. `arbc test`'s `expect PROPERTY;` reads it, so a kept counterexample
// states the property itself; the runtime checks of issue 39 are to read it too.
// tests/drt/drt/claims.py (temporal) is the differential test's statement of the same meaning.
//
// Which records count: deliveries into the property's port, decisions (deliveries and drops) of
// the port's rules, and the port's own container (event records at that port): a property
// reads the container of its port, never another's (docs/design.md#events-and-lifetimes).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/app_model.h"
#include "core/instant.h"
#include "runtime/name_map.h"
#include "runtime/trace_container.h"
#include "runtime/trace_format.h"
#include "runtime/trace_record.h"

namespace arbc {

struct PropertyBreach {
  Nanos from{0};     // the first instant the breach involves (an earlier delivery, a trigger)
  Nanos t{0};        // the instant the run broke the property
  std::string what;  // what happened, in words ("'ask' delivered at 0s and at 250ms")
};

class PropertyWatch {
 public:
  // `port_rules`: the names of the rules into p.port (a response answered by the port, and the
  // decisions whose state a response's `while` reads).
  // `shared`: the port's container kept by the caller, who applies each of its records after
  // before_event(r) and before observe(r) (ClaimWatch, whose checks read the same container:
  // one container per port instead of one per property); null: the watch keeps its own.
  PropertyWatch(model::TemporalProperty p, std::set<std::string> port_rules,
                const TraceContainer* shared = nullptr);

  // With a shared container: an event record of the port, before the caller applies it.
  void before_event(const TraceLine& r);

  // One record of the run, in order. Once broken, later records change nothing.
  void observe(const TraceLine& r);
  void observe(const TraceRecord& r) { observe(trace_line_of(r)); }
  // The run was observed up to `end`: a response trigger whose window closed by then and got no
  // answer breaks the property; one whose window ends later is not judged.
  void finish(Nanos end);

  const std::optional<PropertyBreach>& breach() const { return breach_; }

  // What it remembers of the run that a later delivery may break the property against (the
  // last deliveries, the precedence's arming, the last switch), for a mediator's memory
  // (runtime/mediator_memory.h). The port's events are not in it: the runtime restores them as
  // event records. Nor are response windows still open: a run started again owes them nothing.
  nlohmann::json save() const;
  // Takes a save() back, its instants moved by `shift`; throws nlohmann::json::exception when
  // `saved` is not one.
  void restore(const nlohmann::json& saved, Nanos shift);

 private:
  struct Trigger {
    Nanos t;
    Nanos horizon;
  };

  void container(const TraceLine& r);
  void decision(const TraceLine& r);
  void delivery(const TraceLine& r);
  void respond(const TraceLine& r, const std::set<std::string>& state);
  void close_windows_before(Nanos t);
  void broken(Nanos from, Nanos t, std::string what);

  // The number of a deliverer's name (names_), added when new.
  size_t number(std::string_view name) {
    size_t i = names_.find(name);
    return i != NameIndex::npos ? i : add_name(name);
  }
  size_t add_name(std::string_view name);
  bool is_rule(std::string_view name) const;  // one of the port's rules

  model::TemporalProperty p_;
  // The rules and deliverers it reads, numbered (runtime/name_map.h): each record's name is
  // found once and then compared as a number (it runs on every delivery into the port).
  NameIndex names_;         // the port's rules, p_.rule, p_.other, then any other deliverer
  std::vector<bool> rule_;  // by names_: one of the port's rules
  std::vector<std::optional<Nanos>> last_;  // by names_: its last delivery
  size_t named_rule_, named_other_;         // p_.rule, p_.other
  const TraceContainer& box() const { return shared_ ? *shared_ : own_; }
  TraceContainer own_;  // the port's container, unless shared
  const TraceContainer* shared_ = nullptr;
  bool was_present_ = false;         // before_event(): a response's event, before it
  bool armed_ = false;               // precedence
  std::optional<size_t> last_rule_;  // stability: by names_
  std::optional<Nanos> last_switch_;
  std::vector<Trigger> pending_;  // response triggers not yet answered
  std::optional<PropertyBreach> breach_;
};

// The rules into `port` in `app` (its arbitrated connections), for PropertyWatch.
std::set<std::string> rules_into(const model::App& app, const std::string& port);

}  // namespace arbc
