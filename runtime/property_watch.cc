#include "runtime/property_watch.h"

#include "core/constraint.h"
#include "core/duration_literal.h"
#include "core/instant.h"

namespace arbc {

namespace {

using Kind = model::TemporalProperty::Kind;

std::string at(Nanos t) { return duration_literal(t); }

}  // namespace

std::set<std::string> rules_into(const model::App& app, const std::string& port) {
  std::set<std::string> out;
  for (const model::Connection* c : app.connections_into(port))
    if (c->kind == model::ConnectionKind::Rule) out.insert(c->name);
  return out;
}

PropertyWatch::PropertyWatch(model::TemporalProperty p, std::set<std::string> port_rules,
                             const TraceContainer* shared)
    : p_(std::move(p)), rules_(port_rules.begin(), port_rules.end()), shared_(shared) {}

void PropertyWatch::before_event(const TraceLine& r) {
  if (p_.kind == Kind::Response && !p_.event.empty() && r.event == p_.event)
    was_present_ = box().present_at(p_.event, r.t);
}

void PropertyWatch::broken(Nanos from, Nanos t, std::string what) {
  if (!breach_) breach_ = PropertyBreach{from, t, std::move(what)};
}

void PropertyWatch::observe(const TraceLine& r) {
  if (breach_) return;
  if (r.kind == TraceKind::Event && r.port == p_.port) {
    container(r);
  } else if ((r.kind == TraceKind::Deliver && r.port == p_.port) ||
             (r.kind == TraceKind::Drop && rules_.count(r.connection))) {
    decision(r);
  }
}

// An event record of the port; for a response triggered by an event, its becoming present.
void PropertyWatch::container(const TraceLine& r) {
  if (!shared_) before_event(r), own_.apply(r);
  if (p_.kind != Kind::Response || p_.event.empty() || r.event != p_.event) return;
  close_windows_before(r.t);
  if (!was_present_ && box().present_at(p_.event, r.t))
    pending_.push_back({r.t, later(r.t, p_.window)});
}

void PropertyWatch::decision(const TraceLine& r) {
  if (p_.kind == Kind::Response) {
    close_windows_before(r.t);
    if (breach_) return;
    respond(r, box().present(r.t));
    bool trigger = p_.event.empty() && r.kind == TraceKind::Deliver && r.connection == p_.other;
    if (trigger) pending_.push_back({r.t, later(r.t, p_.window)});
    return;
  }
  if (r.kind == TraceKind::Deliver) delivery(r);
}

// Spacing, absence, precedence and stability read the port's deliveries.
void PropertyWatch::delivery(const TraceLine& r) {
  std::string_view who = r.connection;
  auto named = [&] { return "'" + std::string(who) + "'"; };  // in a breach's text
  Nanos t = r.t;
  if (p_.kind == Kind::Spacing && who == p_.rule) {
    const std::string& before = p_.other.empty() ? p_.rule : p_.other;
    auto it = last_.find(before);
    if (it != last_.end() && t < later(it->second, p_.window)) {
      broken(it->second, t,
             p_.other.empty()
                 ? named() + " delivered at " + at(it->second) + " and at " + at(t)
                 : named() + " delivered at " + at(t) + ", '" + before + "' at " + at(it->second));
    }
  }
  if (p_.kind == Kind::Absence && who == p_.rule && box().present(t).count(p_.event))
    broken(t, t, named() + " delivered at " + at(t) + " with " + p_.event + " present");
  if (p_.kind == Kind::Precedence && who == p_.other) armed_ = true;
  if (p_.kind == Kind::Precedence && who == p_.rule) {
    if (!armed_)
      broken(t, t,
             named() + " delivered at " + at(t) + " with no delivery of '" + p_.other +
                 "' since its last");
    armed_ = false;
  }
  if (p_.kind == Kind::Stability && last_rule_ && who != *last_rule_) {
    if (last_switch_ && t < later(*last_switch_, p_.window))
      broken(*last_switch_, t,
             "the deliverer switched at " + at(*last_switch_) + " and at " + at(t));
    last_switch_ = t;
  }
  // Assigned only when they change: this runs on every delivery (no string copy then).
  if (!last_rule_ || *last_rule_ != who) last_rule_ = std::string(who);
  if (auto it = last_.find(who); it != last_.end())
    it->second = t;
  else
    last_.emplace(who, t);
}

// A decision in a pending trigger's window: a delivery of the rule (of any rule of the port,
// when the port answers) answers it; with `stops`, OTHER delivering again releases it; so does
// the `while` condition false at a decision of the rule.
void PropertyWatch::respond(const TraceLine& r, const std::set<std::string>& state) {
  std::string_view who = r.connection;
  bool deliver = r.kind == TraceKind::Deliver;
  if (p_.stops && deliver && who == p_.other) {
    pending_.clear();
    return;
  }
  bool answers = p_.rule.empty() ? rules_.count(who) > 0 : who == p_.rule;
  if (!answers) return;
  if (deliver || !evaluate(p_.condition, state)) pending_.clear();
}

void PropertyWatch::close_windows_before(Nanos t) {
  for (const Trigger& g : pending_) {
    if (t > g.horizon) {
      broken(g.t, g.horizon,
             "triggered at " + at(g.t) + ", no delivery of " +
                 (p_.rule.empty() ? p_.port : "'" + p_.rule + "'") + " by " + at(g.horizon));
      return;
    }
  }
}

nlohmann::json PropertyWatch::save() const {
  nlohmann::json last = nlohmann::json::object();
  for (const auto& [rule, t] : last_) last[rule] = t.count();
  nlohmann::json out = {{"last", last}, {"armed", armed_}};
  if (last_rule_) out["last_rule"] = *last_rule_;
  if (last_switch_) out["last_switch"] = last_switch_->count();
  return out;
}

void PropertyWatch::restore(const nlohmann::json& saved, Nanos shift) {
  for (const auto& [rule, t] : saved.at("last").items())
    last_[rule] = Nanos(t.get<int64_t>()) + shift;
  armed_ = saved.at("armed").get<bool>();
  if (saved.contains("last_rule")) last_rule_ = saved.at("last_rule").get<std::string>();
  if (saved.contains("last_switch"))
    last_switch_ = Nanos(saved.at("last_switch").get<int64_t>()) + shift;
}

void PropertyWatch::finish(Nanos end) {
  if (breach_ || p_.kind != Kind::Response) return;
  // A window that ends after the run is not judged: the answer might still have come.
  for (const Trigger& g : pending_) {
    if (g.horizon <= end) {
      close_windows_before(kNever);
      return;
    }
  }
}

}  // namespace arbc
