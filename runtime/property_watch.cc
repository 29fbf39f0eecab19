#include "runtime/property_watch.h"

#include "core/constraint.h"
#include "core/duration_literal.h"
#include "core/instant.h"
#include "runtime/same_name.h"

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
    : p_(std::move(p)), shared_(shared) {
  for (const std::string& rule : port_rules) names_.add(rule);
  rule_.assign(names_.size(), true);
  last_.resize(names_.size());
  named_rule_ = number(p_.rule);
  named_other_ = number(p_.other);
}

size_t PropertyWatch::add_name(std::string_view name) {
  size_t i = names_.add(name);
  rule_.resize(names_.size(), false);
  last_.resize(names_.size());
  return i;
}

void PropertyWatch::before_event(const TraceLine& r) {
  if (p_.kind == Kind::Response && !p_.event.empty() && r.event == p_.event)
    was_present_ = box().present_at(p_.event, r.t);
}

void PropertyWatch::broken(Nanos from, Nanos t, std::string what) {
  if (!breach_) breach_ = PropertyBreach{from, t, std::move(what)};
}

void PropertyWatch::observe(const TraceLine& r) {
  if (breach_) return;
  if (r.kind == TraceKind::Event && same_name(r.port, p_.port)) {
    container(r);
  } else if ((r.kind == TraceKind::Deliver && same_name(r.port, p_.port)) ||
             (r.kind == TraceKind::Drop && is_rule(r.connection))) {
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
  size_t who = number(r.connection);
  auto named = [&] { return "'" + std::string(r.connection) + "'"; };  // in a breach's text
  Nanos t = r.t;
  if (p_.kind == Kind::Spacing && who == named_rule_) {
    size_t before = p_.other.empty() ? named_rule_ : named_other_;
    const std::optional<Nanos>& last = last_[before];
    if (last && t < later(*last, p_.window)) {
      broken(*last, t,
             p_.other.empty()
                 ? named() + " delivered at " + at(*last) + " and at " + at(t)
                 : named() + " delivered at " + at(t) + ", '" + p_.other + "' at " + at(*last));
    }
  }
  if (p_.kind == Kind::Absence && who == named_rule_ && box().present(t).count(p_.event))
    broken(t, t, named() + " delivered at " + at(t) + " with " + p_.event + " present");
  if (p_.kind == Kind::Precedence && who == named_other_) armed_ = true;
  if (p_.kind == Kind::Precedence && who == named_rule_) {
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
  last_rule_ = who;
  last_[who] = t;
}

bool PropertyWatch::is_rule(std::string_view name) const {
  size_t i = names_.find(name);
  return i != NameIndex::npos && rule_[i];
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
  bool answers = p_.rule.empty() ? is_rule(who) : who == p_.rule;
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
  for (size_t i = 0; i < names_.size(); ++i)
    if (last_[i]) last[names_.name(i)] = last_[i]->count();
  nlohmann::json out = {{"last", last}, {"armed", armed_}};
  if (last_rule_) out["last_rule"] = names_.name(*last_rule_);
  if (last_switch_) out["last_switch"] = last_switch_->count();
  return out;
}

void PropertyWatch::restore(const nlohmann::json& saved, Nanos shift) {
  for (const auto& [rule, t] : saved.at("last").items())
    last_[number(rule)] = Nanos(t.get<int64_t>()) + shift;
  armed_ = saved.at("armed").get<bool>();
  if (saved.contains("last_rule")) last_rule_ = number(saved.at("last_rule").get<std::string>());
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
