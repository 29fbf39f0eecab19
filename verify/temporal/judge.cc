#include "verify/temporal/judge.h"

#include <map>
#include <optional>
#include <utility>

#include "core/duration_literal.h"
#include "core/instant.h"
#include "core/join.h"
#include "verify/temporal/judge_response.h"
#include "verify/temporal/presence.h"

namespace arbc::verify::temporal {
namespace {

using Kind = ReplayRecord::Kind;

std::string at_times(const std::vector<Nanos>& times) {
  std::vector<std::string> at;
  for (Nanos t : times) at.push_back(duration_literal(t));
  return at.empty() ? std::string("no time") : join(at);
}

bool spacing(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
             std::string* seen) {
  std::vector<Nanos> times;
  for (const ReplayRecord& r : records)
    if (r.kind == Kind::Deliver && r.connection == p.rule) times.push_back(r.t);
  if (spaced_less_than(times, p.window)) return true;
  *seen = "'" + p.rule + "' delivered at " + at_times(times);
  return false;
}

// `never RULE within W after OTHER;`: a delivery of RULE less than W after OTHER's last one.
bool spacing_after(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                   std::string* seen) {
  std::optional<Nanos> last_other;
  std::vector<Nanos> times, other_times;
  for (const ReplayRecord& r : records) {
    if (r.kind != Kind::Deliver) continue;
    if (r.connection == p.other) {
      last_other = r.t;
      other_times.push_back(r.t);
    } else if (r.connection == p.rule) {
      if (last_other && r.t - *last_other < p.window) return true;
      times.push_back(r.t);
    }
  }
  *seen = "'" + p.rule + "' delivered at " + at_times(times) + ", '" + p.other + "' at " +
          at_times(other_times);
  return false;
}

// A delivery is recorded after its connection's accept ran and before a `by priority` rule's
// activity event is set, so the entries seen at the record are the decision state.
bool absence(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
             std::string* seen) {
  Presence event;
  std::vector<Nanos> times;
  for (const ReplayRecord& r : records) {
    if (r.kind != Kind::Deliver) {
      if (r.event == p.event) event.apply(r);
      continue;
    }
    if (r.connection != p.rule) continue;
    if (event.present(r.t)) return true;
    times.push_back(r.t);
  }
  *seen = "'" + p.rule + "' delivered at " + at_times(times) + ", each time without " + p.event;
  return false;
}

bool precedence(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                std::string* seen) {
  bool armed = false;
  std::vector<std::string> order;
  for (const ReplayRecord& r : records) {
    if (r.kind != Kind::Deliver) continue;
    if (r.connection == p.other) {
      armed = true;
    } else if (r.connection == p.rule) {
      if (!armed) return true;
      armed = false;
    } else {
      continue;
    }
    order.push_back(r.connection + " at " + duration_literal(r.t));
  }
  *seen = "the deliveries were " + (order.empty() ? std::string("none") : join(order));
  return false;
}

// Two switches of the delivering rule less than the window apart.
bool stability(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
               std::string* seen) {
  std::string last;
  std::vector<Nanos> switches;
  std::vector<std::string> order;
  for (const ReplayRecord& r : records) {
    if (r.kind != Kind::Deliver) continue;
    order.push_back(r.connection + " at " + duration_literal(r.t));
    if (!last.empty() && r.connection != last) switches.push_back(r.t);
    last = r.connection;
  }
  if (spaced_less_than(switches, p.window)) return true;
  *seen = "the deliveries were " + (order.empty() ? std::string("none") : join(order));
  return false;
}

}  // namespace

// The assumed event's presence at each delivery into the port (a decision the records show)
// against the assumption's monitor: the replay stands in for the feeds, so it must keep what
// the spec assumes of them, or its violation would be one the environment never produces.
bool replay_respects(const model::Assumption& a, const std::vector<ReplayRecord>& records,
                     std::string* broken) {
  Presence event;
  bool armed = false;
  std::optional<Nanos> last_after;  // the timed form: the last delivery of a.after
  for (const ReplayRecord& r : records) {
    if (r.kind != Kind::Deliver) {
      if (r.event == a.event) event.apply(r);
      continue;
    }
    if (a.absent_for) {
      if (last_after && r.t - *last_after < *a.absent_for && event.present(r.t)) {
        *broken = a.event + " was present when '" + r.connection + "' delivered at " +
                  duration_literal(r.t) + ", less than " + duration_literal(*a.absent_for) +
                  " after " + a.after + " delivered at " + duration_literal(*last_after);
        return false;
      }
      if (r.connection == a.after) last_after = r.t;
      continue;
    }
    if (!armed && event.present(r.t)) {
      *broken = a.event + " was present when '" + r.connection + "' delivered at " +
                duration_literal(r.t) + ", before " + a.after + " delivered" +
                (a.until.empty() ? "" : " (or after " + a.until + " did)");
      return false;
    }
    if (r.connection == a.after) armed = true;
    if (!a.until.empty() && r.connection == a.until) armed = false;
  }
  return true;
}

bool spaced_less_than(const std::vector<Nanos>& times, Nanos window) {
  for (size_t i = 1; i < times.size(); ++i)
    if (times[i] - times[i - 1] < window) return true;
  return false;
}

bool replay_violates(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                     std::string* seen) {
  switch (p.kind) {
    case model::TemporalProperty::Kind::Spacing:
      return p.other.empty() ? spacing(p, records, seen) : spacing_after(p, records, seen);
    case model::TemporalProperty::Kind::Absence:
      return absence(p, records, seen);
    case model::TemporalProperty::Kind::Precedence:
      return precedence(p, records, seen);
    case model::TemporalProperty::Kind::Response:
      return response_violated(p, records, seen);
    case model::TemporalProperty::Kind::Stability:
      return stability(p, records, seen);
  }
  return false;
}

}  // namespace arbc::verify::temporal
