// The live view's side of the runtime (runtime/port_status.h): each arbitrated port mediated
// here as the message path would judge its rules now, taken on the runtime's thread.
#include <algorithm>

#include "core/duration_literal.h"
#include "runtime/runtime_internal.h"

namespace arbc {

namespace {

uint64_t losses_of(const ConnectionStats& s) {
  uint64_t n = 0;
  for (const DropReasonInfo& info : kDropReasons)
    if (info.loss) n += s.drops(info.reason);
  return n;
}

}  // namespace

// What keeps c from delivering a message now, in the message path's order (message_path.cc,
// Runtime::selected): out of service, events not known since start, its constraint, its
// throttle. The deliveries-not-yet-answered rule is left out: it is about the message being
// judged (what it answers), and between messages there is none.
std::string Runtime::blocked_now(Connection& c, Nanos t) {
  if (c.quarantined) return "quarantined";
  // As knows_events_of judges, without its side effects (the fail-open report is the
  // decision's to make, at its instant).
  for (const Connection::UnknownEvent& u : c.unknown)
    if (still_unknown(u, t, start_time_)) return unknown_text(u);
  // Its next message is judged on the container as that message's accept leaves it: what
  // every accepting path sets is present then, what it unsets absent (core/effective_guard.h).
  // A twist_mux input's rule reads its own activity, which its message sets: "joystick_active
  // absent" now says nothing about the next joystick command.
  InPort& in = *c.destination;
  auto present = [&](const std::string& e) {
    if (std::find(c.model->must_set.begin(), c.model->must_set.end(), e) != c.model->must_set.end())
      return true;
    if (std::find(c.model->must_unset.begin(), c.model->must_unset.end(), e) !=
        c.model->must_unset.end())
      return false;
    return in.container.has(e, t);
  };
  auto hold_of = [&](const std::string& e) -> std::string {
    for (const auto& other : connections_)
      if (other->destination == &in && other->model->activity_event == e) return other->model->name;
    return "";
  };
  if (!evaluate_with(c.model->constraint, present)) {
    std::string why = why_false(c.model->constraint, present, hold_of);
    return why.empty() ? "its `when` is false" : why;
  }
  if (c.throttle && t < c.last_delivery + *c.throttle)
    return "throttled for " + duration_literal(c.last_delivery + *c.throttle - t);
  return "";
}

std::vector<PortStatus> Runtime::port_status() {
  Nanos t = now();
  std::vector<PortStatus> out;
  size_t k = 0;
  for (const model::ArbitratedPort& ap : app_.arbitrated_ports) {
    auto in = inputs_by_name_.find(ap.port);
    if (in == inputs_by_name_.end() || !in->second->mediated) continue;
    PortStatus p;
    p.port = ap.port;
    uint64_t losses = 0;
    for (const std::string& name : ap.rules) {
      for (auto& cp : connections_) {
        Connection& c = *cp;
        if (c.destination != in->second || c.model->name != name) continue;
        RuleStatus r;
        r.rule = name;
        r.source = c.model->source;
        r.blocked = blocked_now(c, t);
        r.last_arrival = c.last_arrival;
        r.last_delivery = c.last_delivery;
        r.arrived = c.stats.arrived;
        r.delivered = c.stats.delivered;
        r.dropped = c.stats.dropped;
        p.arrived += r.arrived;
        p.delivered += r.delivered;
        for (int i = 0; i < kDropReasonCount; ++i) p.dropped[i] += r.dropped[i];
        losses += losses_of(c.stats);
        if (r.last_delivery > p.last_delivery) {
          p.last_delivery = r.last_delivery;
          p.last_rule = name;
        }
        p.rules.push_back(std::move(r));
      }
    }
    // The selected rule delivered last and may still deliver (a throttle only spaces it).
    for (RuleStatus& r : p.rules) {
      if (r.rule == p.last_rule && (r.blocked.empty() || r.blocked.starts_with("throttled")))
        r.selected = true, p.selected = r.rule;
    }
    if (status_losses_.size() <= k) status_losses_.resize(k + 1, 0);
    summarize_port(p, losses > status_losses_[k]);
    status_losses_[k++] = losses;
    out.push_back(std::move(p));
  }
  return out;
}

void Runtime::post_status(Nanos at) {
  executor_->post(at, [this, at] {
    std::vector<PortStatus> ports = port_status();
    status_at_ = now();
    if (options_.on_status) options_.on_status(now(), ports);
    if (transport_ && transport_->carries_status())
      transport_->publish_status(now(), stamp_clock(), ports);
    post_status(at + options_.status_period);
  });
}

}  // namespace arbc
