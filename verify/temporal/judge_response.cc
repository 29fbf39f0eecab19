#include "verify/temporal/judge_response.h"

#include <map>
#include <set>

#include "core/instant.h"
#include "core/join.h"
#include "core/time_text.h"
#include "verify/temporal/presence.h"

namespace arbc::verify::temporal {
namespace {

using Kind = ReplayRecord::Kind;

// Whether p's condition holds at time t, with the records before index `upto` applied.
bool condition_at(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                  size_t upto, double t) {
  std::set<std::string> events;
  p.condition.collect_events(events);
  std::map<std::string, Presence> state;
  for (size_t i = 0; i < upto; ++i)
    if (records[i].kind != Kind::Deliver && events.count(records[i].event))
      state[records[i].event].apply(records[i]);
  std::set<std::string> present;
  for (const std::string& e : events)
    if (state[e].present(t)) present.insert(e);
  return evaluate(p.condition, present);
}

// The index of the first record after time t (records at t come before a decision at t only
// when they precede it; the messages of the test at t are decided after the records at t).
size_t records_until(const std::vector<ReplayRecord>& records, double t) {
  size_t i = 0;
  while (i < records.size() && records[i].t <= t) ++i;
  return i;
}

// The trigger delivered at records[i] is left unanswered until its window closes.
bool unanswered(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                size_t i, const std::vector<double>& decisions) {
  double t = records[i].t, end = t + p.window;
  for (size_t j = i + 1; j < records.size(); ++j) {
    const ReplayRecord& r = records[j];
    if (!reached(end, r.t)) break;  // past the window (a delivery at its end is in time)
    if (r.kind != Kind::Deliver) continue;
    if (r.connection == p.rule) return false;
    if (p.stops && r.connection == p.other) return false;
  }
  for (double d : decisions) {
    if (d < t || !reached(end, d)) continue;
    if (!condition_at(p, records, records_until(records, d), d)) return false;
  }
  return true;
}

}  // namespace

bool response_violated(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                       const model::TestCase* test, const std::string& rule_source,
                       std::string* seen) {
  std::vector<double> decisions;
  if (test)
    for (const model::TestStep& s : test->steps)
      if (s.kind == model::TestStep::Kind::Input && s.port == rule_source) decisions.push_back(s.t);
  std::vector<std::string> order;
  for (size_t i = 0; i < records.size(); ++i) {
    const ReplayRecord& r = records[i];
    if (r.kind != Kind::Deliver || (r.connection != p.rule && r.connection != p.other)) continue;
    if (r.connection == p.other && unanswered(p, records, i, decisions)) return true;
    order.push_back(r.connection + " at " + time_text(r.t) + "s");
  }
  *seen = "the deliveries were " + (order.empty() ? std::string("none") : join(order)) + ", each " +
          p.other + " answered in time or with the condition false";
  return false;
}

}  // namespace arbc::verify::temporal
