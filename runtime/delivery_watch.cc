#include "runtime/delivery_watch.h"

#include <algorithm>

#include "core/duration_literal.h"
#include "core/join.h"

namespace arbc {

namespace {

const std::set<std::string>& present_in(
    const std::unordered_map<std::string, TraceContainer>& boxes, const std::string& port,
    Nanos t) {
  static const std::set<std::string> kNone;
  auto it = boxes.find(port);
  return it == boxes.end() ? kNone : it->second.present(t);
}

std::string value_text(const Value* v) { return v ? v->to_json() : "?"; }

}  // namespace

DeliveryWatch::DeliveryWatch(const model::App& app, DataClaims* claims,
                             const std::unordered_map<std::string, TraceContainer>& boxes)
    : claims_(claims), boxes_(boxes) {
  std::map<std::string, size_t> when;  // resource -> the claim of its `when`
  if (claims_) {
    const std::vector<model::DataClaim>& all = claims_->claims();
    for (size_t i = 0; i < all.size(); ++i) {
      if (all[i].kind == model::DataClaim::Kind::Assert)
        asserts_.push_back({i, all[i].port, all[i].rule, all[i].text});
      else
        when[all[i].resource] = i;
    }
  }
  // Only ports mediated here decide (boxes_ holds theirs); a resource is watched where all its
  // ports are.
  auto here = [&](const std::string& port) { return boxes_.count(port) > 0; };
  asserts_.erase(std::remove_if(asserts_.begin(), asserts_.end(),
                                [&](const Assert& a) { return !here(a.port); }),
                 asserts_.end());
  for (const model::Resource& r : app.resources) {
    auto w = when.find(r.name);
    if (r.uses && w == when.end()) continue;  // its `when` cannot be judged here
    if (!std::all_of(r.ports.begin(), r.ports.end(), here)) continue;
    Watched watched{&r, std::nullopt, 0, std::nullopt};
    if (w != when.end()) watched.uses = w->second;
    resources_.push_back(std::move(watched));
    resource_ports_.insert(r.ports.begin(), r.ports.end());
  }
}

std::vector<std::string> DeliveryWatch::watched() const {
  std::vector<std::string> out;
  for (const Assert& a : asserts_) out.push_back(a.text);
  for (const Watched& w : resources_) out.push_back("resource " + w.r->name);
  return out;
}

// The records right after a delivery at its instant are its effects (its delivery events, a
// `by priority` activity event): the state the delivery left is known at the first other one.
void DeliveryWatch::before(const TraceLine& r) {
  for (Watched& w : resources_)
    if (w.last && !w.last->settled && !(r.kind == TraceKind::Event && r.t == w.last->t))
      settle(w, w.last->t);
  if (r.kind != TraceKind::Event) return;
  auto port = resource_ports_.find(r.port);
  if (port != resource_ports_.end()) was_present_ = present(r, *port);
}

bool DeliveryWatch::present(const TraceLine& r, const std::string& port) const {
  auto it = boxes_.find(port);
  return it != boxes_.end() && it->second.present_at(r.event, r.t);
}

void DeliveryWatch::after(const TraceLine& r, const std::string& port) {
  if (r.kind != TraceKind::Event || !watches_port(port)) return;
  if (present(r, port) == was_present_) return;  // a refresh, or an expiry's late record
  for (Watched& w : resources_)
    if (std::find(w.r->ports.begin(), w.r->ports.end(), port) != w.r->ports.end()) ++w.changes;
}

void DeliveryWatch::settle(Watched& w, Nanos t) {
  Use& u = *w.last;
  u.settled = true;
  u.changes = w.changes;
  u.state.clear();
  for (const std::string& p : w.r->ports) u.state.push_back(present_in(boxes_, p, t));
}

// No event of the resource's ports was set, unset or lapsed since the last use settled.
bool DeliveryWatch::same_state(const Watched& w, Nanos t) const {
  const Use& u = *w.last;
  if (!u.settled || u.changes != w.changes) return false;
  for (size_t i = 0; i < w.r->ports.size(); ++i)
    if (present_in(boxes_, w.r->ports[i], t) != u.state[i]) return false;
  return true;
}

bool DeliveryWatch::uses(const Watched& w, const Value* v) {
  if (!w.uses) return true;  // every command uses it
  if (!v) return true;       // no value to judge: the proof's `when` may hold
  std::string why;
  // A `when` without a value (it reads one that does not exist) does not hold, as in the proof.
  return claims_->evaluate(*w.uses, *v, &why) == DataClaims::Outcome::Holds;
}

void DeliveryWatch::delivered(const TraceLine& r, const std::string& port,
                              std::vector<Breach>* out) {
  // Texts only for a breach: this runs on every delivery (bench/figures/runtime_checks.sh).
  auto at = [&] { return " into " + port + " at " + duration_literal(r.t); };
  for (const Assert& a : asserts_) {
    if (a.port != port || a.rule != r.connection || !r.value) continue;
    std::string why;
    DataClaims::Outcome o = claims_->evaluate(a.claim, *r.value, &why);
    if (o == DataClaims::Outcome::Holds) continue;
    out->push_back({a.text, "'" + a.rule + "' delivered " + value_text(r.value) + at() +
                                (o == DataClaims::Outcome::Fails ? ", for which it is false"
                                                                 : ", for which " + why)});
  }
  for (Watched& w : resources_) {
    if (std::find(w.r->ports.begin(), w.r->ports.end(), port) == w.r->ports.end()) continue;
    if (!uses(w, r.value)) continue;
    if (w.last && w.last->port != port && same_state(w, r.t))
      out->push_back({"resource " + w.r->name,
                      "'" + w.last->rule + "' into " + w.last->port + " at " +
                          duration_literal(w.last->t) + " and '" + std::string(r.connection) + "'" +
                          at() + " both delivered a command that uses it (" +
                          value_text(w.last->value ? &*w.last->value : nullptr) + ", " +
                          value_text(r.value) + ") in one event state, which no event of its " +
                          "ports changed in between"});
    w.last = Use{port, std::string(r.connection), std::nullopt, r.t, false, 0, {}};
    if (r.value) w.last->value = *r.value;
  }
}

}  // namespace arbc
