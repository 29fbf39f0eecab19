#include "verify/temporal/judge_response.h"

#include <map>
#include <set>

#include "core/duration_literal.h"
#include "core/join.h"
#include "verify/temporal/presence.h"

namespace arbc::verify::temporal {
namespace {

using Kind = ReplayRecord::Kind;

// Whether p's condition holds at time t, with the records before index `upto` applied.
bool condition_at(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                  size_t upto, Nanos t) {
  std::set<std::string> events;
  p.condition.collect_events(events);
  std::map<std::string, Presence> state;
  for (size_t i = 0; i < upto; ++i)
    if (events.count(records[i].event)) state[records[i].event].apply(records[i]);
  std::set<std::string> present;
  for (const std::string& e : events)
    if (state[e].present(t)) present.insert(e);
  return evaluate(p.condition, present);
}

// The trigger at records[i] (a delivery, or the event's onset) is left unanswered until its
// window closes: no delivery of the rule (of any rule, when the port answers) after it, nor
// (with `stops`) of the trigger, and the condition held whenever an answering rule decided.
// The records are in the order the runtime did them, as the model's steps are.
bool unanswered(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                size_t i) {
  Nanos end = records[i].t + p.window;
  for (size_t j = i + 1; j < records.size(); ++j) {
    const ReplayRecord& r = records[j];
    if (r.t > end) break;  // past the window (a delivery at its end is in time)
    if (r.kind != Kind::Deliver && r.kind != Kind::Drop) continue;
    if (p.stops && r.kind == Kind::Deliver && r.connection == p.other) return false;
    if (r.connection != p.rule && !p.rule.empty()) continue;
    if (r.kind == Kind::Deliver) return false;
    // A decision with the state the records before it leave.
    if (!condition_at(p, records, j, r.t)) return false;
  }
  return true;
}

}  // namespace

bool response_violated(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                       std::string* seen) {
  std::vector<std::string> order;
  Presence event;  // an event trigger: its entries in the port, record by record
  for (size_t i = 0; i < records.size(); ++i) {
    const ReplayRecord& r = records[i];
    if (r.kind == Kind::Drop) continue;
    if (r.kind != Kind::Deliver) {
      if (p.event.empty() || r.event != p.event) continue;
      bool before = event.present(r.t);
      event.apply(r);
      if (before || !event.present(r.t)) continue;
      if (unanswered(p, records, i)) return true;
      order.push_back(p.event + " present at " + duration_literal(r.t));
      continue;
    }
    // A delivery of the trigger opens a window that only a later delivery answers (with the
    // port answering, the trigger rule is one of the port's rules too).
    if (r.connection == p.other && unanswered(p, records, i)) return true;
    if (r.connection == p.other || r.connection == p.rule || p.rule.empty())
      order.push_back(r.connection + " at " + duration_literal(r.t));
  }
  std::string trigger = p.event.empty() ? p.other : p.event;
  *seen = "the deliveries and triggers were " +
          (order.empty() ? std::string("none") : join(order)) + ", each " + trigger +
          " answered in time or with the condition false";
  return false;
}

}  // namespace arbc::verify::temporal
