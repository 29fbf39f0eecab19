#include "runtime/claim_watch.h"

#include <algorithm>

#include "core/constraint.h"
#include "core/duration_literal.h"
#include "core/instant.h"
#include "core/join.h"
#include "core/monitor_digests.h"

namespace arbc {

namespace {

std::string group_text(const model::ExclusiveGroup& g) {
  return "exclusive { " + join(g.events, ", ") + " }";
}

// The events some connection into `port` can set into its container (feeds, monitors, delivery
// and activity events); nullopt when a `script` rule may set any.
std::optional<std::set<std::string>> fed_into(const model::App& app, const std::string& port) {
  std::set<std::string> fed;
  for (const model::Connection* c : app.connections_into(port)) {
    if (c->opaque) return std::nullopt;
    fed.insert(c->sets.begin(), c->sets.end());
    fed.insert(c->must_set.begin(), c->must_set.end());
    if (!c->activity_event.empty()) fed.insert(c->activity_event);
  }
  return fed;
}

// Past this many events of an invariant not fed into a port, it is not watched there: each
// decision would try every value of them.
constexpr size_t kMaxUnfed = 10;

// Whether `f` holds in `state` for some presence of the `unfed` events (absent from `state`).
bool holds_for_some(const Constraint& f, const std::set<std::string>& state,
                    const std::vector<std::string>& unfed) {
  if (evaluate(f, state)) return true;
  for (uint32_t m = 1; m < (1u << unfed.size()); ++m) {
    std::set<std::string> s = state;
    for (size_t i = 0; i < unfed.size(); ++i)
      if (m >> i & 1) s.insert(unfed[i]);
    if (evaluate(f, s)) return true;
  }
  return false;
}

}  // namespace

ClaimWatch::ClaimWatch(const model::App& app, const Scope& scope) : app_(app) {
  auto module = [](const std::string& port) {  // of "Module.port"
    return std::string_view(port).substr(0, port.find('.'));
  };
  std::function<bool(const std::string&)> here = [&](const std::string& port) {
    return scope.mediated.contains(module(port));
  };
  std::set<std::string> read_here;  // sources of connections into ports mediated here
  for (const model::Connection& c : app.connections)
    if (here(c.destination)) read_here.insert(c.source);
  std::set<std::string> mediated;
  for (const model::ArbitratedPort& p : app.arbitrated_ports)
    if (here(p.port)) boxes_[p.port], decides_ = true, mediated.insert(p.port);
  decisions_.emplace(app, here, scope.states_known,
                     [this](const std::string& claim, Nanos t, const std::string& what) {
                       violated(claim, t, what, false);
                     });
  number_names(app, here);
  assumptions_over_events(app, mediated);
  for (const model::TemporalProperty& p : app.temporal) {
    if (!here(p.port)) continue;
    // Observed where a record is about its port (a rule's or an arbitrated port's).
    if (size_t slot = port_index_.find(p.port); slot != NameIndex::npos)
      slots_[slot].properties.push_back(properties_.size());
    auto box = boxes_.find(p.port);  // the same container for the checks and the properties
    properties_.push_back(std::make_unique<PropertyWatch>(
        p, rules_into(app, p.port), box == boxes_.end() ? nullptr : &box->second));
    property_text_.push_back(model::temporal_property_text(p));
    property_broken_.push_back(false);
  }
  for (const model::Assumption& a : app.assumptions) {
    if (!here(a.port)) continue;
    if (size_t slot = port_index_.find(a.port); slot != NameIndex::npos)
      slots_[slot].assumed.push_back(assumed_.size());
    assumed_.push_back({&a, false, std::nullopt});
  }
  for (const model::SourceRate& r : app.rates) {
    if (!read_here.count(r.port)) continue;
    size_t source = source_index_.add(r.port);
    if (source == rates_of_source_.size()) rates_of_source_.emplace_back();
    rates_of_source_[source].push_back(rates_.size());
    rates_.push_back(
        {&r, Nanos{0}, false, scope.test || !scope.hosted.contains(module(r.port)), scope.test});
  }
  rates_changed();
  delivered_ = std::make_unique<DeliveryWatch>(app, nullptr, boxes_);
}

// Numbers the ports and rules mediated here: a record then finds what it is about with one
// search, and the checks read lists by number (observe() runs on every message).
void ClaimWatch::number_names(const model::App& app,
                              const std::function<bool(const std::string&)>& here) {
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    if (!here(p.port)) continue;
    if (port_index_.add(p.port) < slots_.size()) continue;
    slots_.emplace_back();
    slots_.back().box = &boxes_.at(p.port);
  }
  for (const model::Connection& c : app.connections) {
    if (!here(c.destination) || c.kind != model::ConnectionKind::Rule) continue;
    size_t port = port_index_.add(c.destination);
    if (port == slots_.size()) slots_.emplace_back();  // not arbitrated: its box comes later
    RuleSlot rule{port, decisions_->rule_of(c.name)};
    size_t i = rule_index_.add(c.name);
    if (i == rules_.size())
      rules_.push_back(rule);
    else
      rules_[i] = rule;  // a second connection of the name: the last one counts
  }
}

bool ClaimWatch::load_claims(const std::string& app_dir, std::string* err) {
  std::string text;
  if (!model::read_claims_script(app_, app_dir, &text, err)) return false;
  if (text.empty()) return true;
  data_claims_ = DataClaims::load(app_, text, app_.claims_script, err);
  if (!data_claims_) return false;
  delivered_ = std::make_unique<DeliveryWatch>(app_, data_claims_.get(), boxes_);
  return true;
}

// Where each `exclusive` group and `invariant` is watched. A port's proof reads the events its
// rules and asserts read, closed under the groups and invariants that mention them, each free
// (docs/design.md#the-proof); its container holds only the events fed into it, the others never
// present. So an invariant is judged in a port fed some of its events, true when some value of
// the others makes it true (what that port's proof assumed of the state); a group where two of
// its events are fed. One fed into no port of the app is watched nowhere, and said to be (by a
// process that decides something: one that mediates nothing says nothing).
void ClaimWatch::assumptions_over_events(const model::App& app,
                                         const std::set<std::string>& mediated) {
  std::map<std::string, std::optional<std::set<std::string>>> fed;  // every arbitrated port's
  for (const model::ArbitratedPort& p : app.arbitrated_ports) fed[p.port] = fed_into(app, p.port);
  auto count_fed = [](const std::optional<std::set<std::string>>& into,
                      const std::set<std::string>& events, std::vector<std::string>* unfed) {
    size_t n = 0;
    for (const std::string& e : events)
      if (!into || into->count(e))
        ++n;
      else if (unfed)
        unfed->push_back(e);
    return n;
  };
  auto why = [](const std::set<std::string>& events) {
    return ": no port is fed " +
           join(std::vector<std::string>(events.begin(), events.end()), ", ") +
           " (no rule or assert reads them), so no proof rests on it and no run can see it broken";
  };
  for (const model::ExclusiveGroup& g : app.exclusive_groups) {
    std::set<std::string> events(g.events.begin(), g.events.end());
    bool anywhere = false, here = false;
    for (const auto& [port, into] : fed) {
      if (count_fed(into, events, nullptr) < 2) continue;
      anywhere = true, here = here || mediated.count(port);
    }
    if (here) groups_watched_.push_back("assumption " + group_text(g));
    if (!anywhere && decides_) unwatched_.push_back("assumption " + group_text(g) + why(events));
  }
  for (const model::Invariant& inv : app.invariants) {
    std::set<std::string> events;
    inv.formula.collect_events(events);
    if (events.empty()) continue;  // `invariant true;`: nothing of a run to watch
    bool anywhere = false, here = false;
    for (const auto& [port, into] : fed) {
      std::vector<std::string> unfed;
      if (count_fed(into, events, &unfed) == 0 || unfed.size() > kMaxUnfed) continue;
      anywhere = true;
      if (!mediated.count(port)) continue;
      here = true;
      slots_[port_index_.find(port)].guards.push_back({&inv, std::move(unfed)});
    }
    std::string text = "assumption invariant " + inv.formula.to_string();
    if (here) invariants_watched_.push_back(text);
    if (!anywhere && decides_) unwatched_.push_back(text + why(events));
  }
}

void ClaimWatch::start(Nanos t) {
  start_ = t;
  for (Rate& rate : rates_) rate.last = std::max(rate.last, t);
  rates_changed();
}

// An app whose only assumptions cannot be watched still has that to say.
bool ClaimWatch::empty() const { return size() == 0 && unwatched_.empty(); }

size_t ClaimWatch::size() const {
  return decisions_->size() + delivered_->watched().size() + properties_.size() + assumed_.size() +
         rates_.size() + groups_watched_.size() + invariants_watched_.size();
}

std::vector<std::string> ClaimWatch::watched() const {
  std::vector<std::string> out = decisions_->claims();
  std::vector<std::string> delivered = delivered_->watched();
  out.insert(out.end(), delivered.begin(), delivered.end());
  out.insert(out.end(), property_text_.begin(), property_text_.end());
  out.insert(out.end(), groups_watched_.begin(), groups_watched_.end());
  out.insert(out.end(), invariants_watched_.begin(), invariants_watched_.end());
  for (const Assumed& s : assumed_) out.push_back("assumption " + model::assumption_text(*s.a));
  for (const Rate& rate : rates_)
    out.push_back("assumption given " + rate.r->port + " every " +
                  duration_literal(rate.r->period));
  return out;
}

void ClaimWatch::violated(const std::string& claim, Nanos t, std::string what, bool assumption) {
  if (!reported_.insert(claim).second) return;
  violations_.push_back({t, claim, std::move(what), assumption});
}

void ClaimWatch::watch(const TraceLine& r, Trace& trace) {
  size_t known = violations_.size();
  observe(r);
  if (violations_.size() > known) breach_lines(known, r.t, trace);
}

// A trace line for each violation from the `from`-th on, written at `t` (after the record, or
// at the end, that showed it).
void ClaimWatch::breach_lines(size_t from, Nanos t, Trace& trace) const {
  for (size_t i = from; i < violations_.size(); ++i) {
    const ClaimViolation& v = violations_[i];
    trace.breach(t, (v.assumption ? "assumption " : "") + v.claim,
                 "broken at " + duration_literal(v.t) + ": " + v.what);
  }
}

void ClaimWatch::observe(const TraceLine& r) {
  rate_gaps(r.t);
  // Asserts over data and resources: most apps have none, and then nothing of a record matters.
  if (!delivered_->empty()) delivered_->before(r);
  PortSlot* slot = nullptr;  // the port the record is about, if any
  if (r.kind == TraceKind::Publish) {
    published(r);
  } else if (r.kind == TraceKind::Event) {
    slot = event_record(r);
  } else if (r.kind == TraceKind::Deliver ||
             (r.kind == TraceKind::Drop && r.reason != DropReason::Feed)) {  // feeds: no rule
    slot = decided(r);
  }
  // A property reads only its port's events, deliveries and drops (runtime/property_watch.h).
  if (!slot) return;
  for (size_t i : slot->properties) {
    if (property_broken_[i]) continue;
    properties_[i]->observe(r);
    property_breached(i);
  }
}

void ClaimWatch::published(const TraceLine& r) {
  size_t source = source_index_.find(r.port);
  if (source == NameIndex::npos) return;
  for (size_t i : rates_of_source_[source]) {
    Rate& rate = rates_[i];
    Nanos deadline = later(rate.last, rate.r->period);
    if (rate.window && !rate.awaiting_first && !rate.broken && r.t > deadline)
      rate_broken(rate, deadline, r.t);
    rate.last = r.t, rate.awaiting_first = false;
  }
  rates_changed();
}

ClaimWatch::PortSlot* ClaimWatch::event_record(const TraceLine& r) {
  size_t port = port_index_.find(r.port);
  if (port == NameIndex::npos || !slots_[port].box) return nullptr;
  PortSlot& slot = slots_[port];
  for (size_t i : slot.properties) properties_[i]->before_event(r);
  slot.box->apply(r);
  if (!delivered_->empty()) delivered_->after(r, port_index_.name(port));
  if (r.op == "set")
    for (size_t i : slot.assumed)
      if (assumed_[i].a->event == r.event) reported(assumed_[i], r);
  return &slot;
}

// A decision (a delivery, or a drop that is not a feed's) of a rule into a port mediated here.
ClaimWatch::PortSlot* ClaimWatch::decided(const TraceLine& r) {
  size_t i = rule_index_.find(r.connection);
  if (i == NameIndex::npos) return nullptr;
  const RuleSlot& rule = rules_[i];
  PortSlot& slot = slots_[rule.port];
  const std::string& port = port_index_.name(rule.port);
  if (!slot.box) slot.box = &boxes_[port];
  const std::set<std::string>& state = slot.box->present(r.t);
  uint64_t version = slot.box->version();
  if (version != slot.judged_version) decision(slot, port, r.t, state);
  slot.judged_version = version;
  if (rule.decision != NameIndex::npos) decisions_->decision(rule.decision, r, state, version);
  for (size_t a : slot.assumed) assumption(assumed_[a], port, r, state);
  if (r.kind == TraceKind::Deliver && !delivered_->empty()) delivered(r, port);
  return &slot;
}

void ClaimWatch::delivered(const TraceLine& r, const std::string& port) {
  std::vector<DeliveryWatch::Breach> breaches;
  delivered_->delivered(r, port, &breaches);
  for (DeliveryWatch::Breach& b : breaches) violated(b.claim, r.t, std::move(b.what), false);
}

void ClaimWatch::property_breached(size_t i) {
  const auto& b = properties_[i]->breach();
  if (!b) return;
  property_broken_[i] = true;
  violated(property_text_[i], b->t, b->what, false);
}

// The assumptions over the state of the port at a rule's decision: exclusive groups and the
// invariants watched there (the proof reads every state as satisfying them).
void ClaimWatch::decision(const PortSlot& slot, const std::string& port, Nanos t,
                          const std::set<std::string>& state) {
  for (const model::ExclusiveGroup& g : app_.exclusive_groups) {
    size_t n = 0;  // counted first: the text only for a breach (this runs at every decision)
    for (const std::string& e : g.events) n += state.count(e);
    if (n < 2) continue;
    std::vector<std::string> both;
    for (const std::string& e : g.events)
      if (state.count(e)) both.push_back(e);
    violated(
        group_text(g), t,
        join(both, ", ", " and ") + " present together in " + port + " at " + duration_literal(t),
        true);
  }
  for (const Guard& g : slot.guards) {
    if (holds_for_some(g.inv->formula, state, g.unfed)) continue;
    violated("invariant " + g.inv->formula.to_string(), t,
             "false in " + port + " at " + duration_literal(t) +
                 " (events present: " + DecisionWatch::events_present(state) +
                 (g.unfed.empty() ? ""
                                  : "; whatever " + join(g.unfed, ", ", " and ") +
                                        ", not fed into " + port + ", may be") +
                 ")",
             true);
  }
}

// `assume E only after A [until U]` and `assume not E for D after A`, at each decision into the
// port, as docs/language.md#environment-assumptions states them.
void ClaimWatch::assumption(Assumed& s, const std::string& port, const TraceLine& r,
                            const std::set<std::string>& state) {
  if (state.count(s.a->event) > 0) present(s, port, r.t, "");
  if (r.kind != TraceKind::Deliver) return;
  if (r.connection == s.a->after) s.armed = true, s.last_after = r.t;
  if (!s.a->until.empty() && r.connection == s.a->until) s.armed = false;
}

// The assumed event reported into its port (a feed set it): the assumption speaks of what the
// environment reports, so a report while it forbids one breaks it even if no decision reads
// the state before the event lapses (the proof constrains the state after every step too,
// verify/temporal/assumption.cc): a response to the event is otherwise owed from a report the
// proof ruled out (drt seed 12001 spec 118).
void ClaimWatch::reported(Assumed& s, const TraceLine& r) {
  present(s, r.port, r.t, " (reported by " + std::string(r.owner) + ")");
}

void ClaimWatch::present(Assumed& s, std::string_view port, Nanos t, const std::string& how) {
  const model::Assumption& a = *s.a;
  std::string at = " in " + std::string(port) + " at " + duration_literal(t) + how;
  if (a.absent_for) {
    if (s.last_after && t < later(*s.last_after, *a.absent_for))
      violated(model::assumption_text(a), t,
               a.event + " present" + at + ", " + duration_literal(t - *s.last_after) + " after '" +
                   a.after + "' delivered",
               true);
  } else if (!s.armed) {
    violated(model::assumption_text(a), t,
             a.event + " present" + at + " with no delivery of '" + a.after + "'" +
                 (a.until.empty() || !s.last_after ? "" : " since the last of '" + a.until + "'"),
             true);
  }
}

// `given M.p every D`: nothing from M.p for more than D (from the start) breaks it.
void ClaimWatch::rate_gaps(Nanos t) {
  if (t <= next_gap_) return;  // every rate still has time (most records: the common case)
  for (Rate& rate : rates_) {
    Nanos deadline = later(rate.last, rate.r->period);
    // A test's source: judged only by its next message (window_gap), since it is not owed
    // anything after its last one and no record says which one that is before the end.
    if (t <= deadline || rate.broken || rate.awaiting_first || rate.window) continue;
    rate_broken(rate, deadline, t);
  }
  rates_changed();
}

// The earliest instant past which rate_gaps() may find a gap, after a rate changed.
void ClaimWatch::rates_changed() {
  next_gap_ = kNever;
  for (const Rate& rate : rates_)
    if (!rate.broken && !rate.awaiting_first && !rate.window)
      next_gap_ = std::min(next_gap_, later(rate.last, rate.r->period));
}

void ClaimWatch::rate_broken(Rate& rate, Nanos deadline, Nanos t) {
  rate.broken = true;
  violated("given " + rate.r->port + " every " + duration_literal(rate.r->period), deadline,
           "nothing from " + rate.r->port + " between " + duration_literal(rate.last) + " and " +
               duration_literal(t),
           true);
}

void ClaimWatch::finish(Nanos end, Trace* trace) {
  if (finished_) return;
  finished_ = true;
  size_t known = violations_.size();
  judge_end(end);
  if (trace) breach_lines(known, end, *trace);
}

void ClaimWatch::judge_end(Nanos end) {
  rate_gaps(end);
  for (Rate& rate : rates_) {
    if (rate.window || !rate.awaiting_first || end <= later(rate.last, rate.r->period)) continue;
    violated("given " + rate.r->port + " every " + duration_literal(rate.r->period), end,
             "nothing from " + rate.r->port + " from the start (" + duration_literal(rate.last) +
                 ") to the end of the run (" + duration_literal(end) + "): it never published",
             true);
  }
  for (size_t i = 0; i < properties_.size(); ++i) {
    if (property_broken_[i]) continue;
    properties_[i]->finish(end);
    property_breached(i);
  }
}

nlohmann::json ClaimWatch::save() const {
  nlohmann::json properties = nlohmann::json::array(), assumed = nlohmann::json::array(),
                 broken = nlohmann::json::array();
  for (size_t i = 0; i < properties_.size(); ++i)
    properties.push_back({{"claim", property_text_[i]}, {"state", properties_[i]->save()}});
  for (const Assumed& s : assumed_) {
    nlohmann::json a = {{"claim", model::assumption_text(*s.a)}, {"armed", s.armed}};
    if (s.last_after) a["last_after"] = s.last_after->count();
    assumed.push_back(a);
  }
  for (const ClaimViolation& v : violations_)
    broken.push_back({{"claim", v.claim}, {"assumption", v.assumption}});
  return {{"properties", properties}, {"assumptions", assumed}, {"broken", broken}};
}

bool ClaimWatch::load(const nlohmann::json& saved, std::string* error) {
  if (saved.is_object() && saved.empty()) return true;  // written with the checks off
  try {
    const nlohmann::json& properties = saved.at("properties");
    const nlohmann::json& assumed = saved.at("assumptions");
    bool fits = properties.size() == properties_.size() && assumed.size() == assumed_.size();
    for (size_t i = 0; fits && i < properties_.size(); ++i) {
      fits = properties[i].at("claim") == property_text_[i];
      PropertyWatch copy = *properties_[i];
      copy.restore(properties[i].at("state"), Nanos(0));  // throws when it is not a save()
    }
    for (size_t i = 0; fits && i < assumed_.size(); ++i)
      fits = assumed[i].at("claim") == model::assumption_text(*assumed_[i].a);
    for (const nlohmann::json& b : saved.at("broken"))
      fits = fits && b.at("claim").is_string() && b.at("assumption").is_boolean();
    if (!fits) {
      *error =
          "its runtime checks watch other claims than this mediator's (another --mediate?); "
          "start it with the --mediate it had, or remove the file to start with no memory";
      return false;
    }
  } catch (const nlohmann::json::exception& e) {
    *error = std::string("its runtime checks' part is not one this arbc wrote (") + e.what() +
             "); remove the file to start this mediator with no memory";
    return false;
  }
  loaded_ = saved;
  return true;
}

// A claim broken before the restart stays broken: the proof stopped covering the run there,
// and a run that goes on from it is no more covered. It is reported again at this run's start.
void ClaimWatch::resume(Nanos shift) {
  if (loaded_.is_null()) return;
  for (size_t i = 0; i < properties_.size(); ++i)
    properties_[i]->restore(loaded_["properties"][i]["state"], shift);
  for (size_t i = 0; i < assumed_.size(); ++i) {
    const nlohmann::json& a = loaded_["assumptions"][i];
    assumed_[i].armed = a["armed"].get<bool>();
    if (a.contains("last_after"))
      assumed_[i].last_after = Nanos(a["last_after"].get<int64_t>()) + shift;
  }
  for (const nlohmann::json& b : loaded_["broken"]) {
    std::string claim = b["claim"].get<std::string>();
    for (size_t i = 0; i < properties_.size(); ++i)
      if (property_text_[i] == claim) property_broken_[i] = true;
    violated(claim, start_,
             "broken before this mediator started again (the earlier run's "
             "report says how); not watched since",
             b["assumption"].get<bool>());
  }
  loaded_ = nullptr;
}

}  // namespace arbc
