#include "harness/test_expect.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/duration_literal.h"
#include "harness/claim_expect.h"
#include "harness/value_spec_text.h"
#include "report/run_timeline.h"
#include "runtime/property_watch.h"

namespace arbc::harness {

namespace {

// A received value as a spec literal, fields in the order of the port's type, as the
// expectation it is compared with is written.
std::string text_of(const Value& v, const std::string& port, const TestRun& run) {
  const model::Port* p = run.app ? run.app->find_port(port) : nullptr;
  return value_spec_text(v, p && p->type ? p->type.get() : nullptr);
}

bool in_window(Nanos t, const model::Expectation& e) { return e.from <= t && t <= e.to; }

std::string window(const model::Expectation& e) {
  if (e.to == kNever)
    return e.from == Nanos(0) ? "during the test" : "from " + duration_literal(e.from);
  if (e.from == e.to) return "at " + duration_literal(e.from);
  return "between " + duration_literal(e.from) + " and " + duration_literal(e.to);
}

// When nothing reached the port in the window: the value it received closest in time outside
// it, if any, so that an expectation with the wrong time (or the wrong value at another time)
// says what to change rather than leaving the reader to search the trace.
std::string nearest_outside(const model::Expectation& e, const TestRun& run) {
  const Received* best = nullptr;
  Nanos best_gap = kNever;
  for (const Received& r : run.received) {
    if (r.port != e.port) continue;
    Nanos gap = r.t < e.from ? e.from - r.t : r.t - e.to;
    // Prefer the expected value over a closer other one: it is the likelier mistake.
    bool wanted = !e.value || near_equal(*e.value, r.value);
    bool best_wanted = best && (!e.value || near_equal(*e.value, best->value));
    if (!best || (wanted && !best_wanted) || (wanted == best_wanted && gap < best_gap)) {
      best = &r;
      best_gap = gap;
    }
  }
  if (!best) return "";
  if (!e.value || near_equal(*e.value, best->value))
    return "; it received that value at " + duration_literal(best->t);
  return "; the nearest it received was " + text_of(best->value, e.port, run) + " at " +
         duration_literal(best->t);
}

std::string check_receives(const model::Expectation& e, const TestRun& run) {
  std::vector<const Received*> got;
  for (const Received& r : run.received) {
    if (r.port == e.port && in_window(r.t, e)) got.push_back(&r);
  }
  if (e.kind == model::Expectation::Kind::Nothing) {
    if (got.empty()) return "";
    return "but " + e.port + " received " + text_of(got.front()->value, e.port, run) + " at " +
           duration_literal(got.front()->t) + " (from " + got.front()->connection + ")";
  }
  for (const Received* r : got) {
    if (!e.value || near_equal(*e.value, r->value)) return "";
  }
  if (got.empty())
    return "but nothing reached " + e.port + " " + window(e) + nearest_outside(e, run);
  std::string out = "but " + e.port + " received other values " + window(e) + ":";
  for (size_t i = 0; i < got.size() && i < 5; ++i)
    out += "\n    " + duration_literal(got[i]->t) + " " + text_of(got[i]->value, e.port, run);
  return out;
}

std::string check_drops(const model::Expectation& e, const TestRun& run) {
  std::string seen;
  size_t count = 0;
  for (const TraceRecord& r : run.records) {
    if (r.connection != e.connection || !in_window(r.t, e)) continue;
    if (r.kind == TraceKind::Drop) {
      if (e.reason.empty() || e.reason == drop_reason_name(r.reason)) return "";
      if (count++ < 5)
        seen += ", dropped (" + std::string(drop_reason_name(r.reason)) + ") at " +
                duration_literal(r.t);
    } else if (r.kind == TraceKind::Deliver && count++ < 5) {
      seen += ", delivered at " + duration_literal(r.t);
    }
  }
  if (seen.empty()) return "but no message reached " + e.connection + " " + window(e);
  return "but " + e.connection + " " + seen.substr(2);
}

// `RULE delivers [nothing]`: only the rule's deliveries count, not its drops, so a drop of
// another message at the same instant (the rule not selected for it) cannot stand in for the
// one the expectation is about, as it can for `drops` without a reason.
std::string check_delivers(const model::Expectation& e, const TraceRecord* first,
                           const TestRun& run) {
  if (e.kind == model::Expectation::Kind::DeliversNothing) {
    if (!first) return "";
    return "but " + e.connection + " delivered at " + duration_literal(first->t) + " to " +
           first->port;
  }
  if (first) return "";
  std::optional<Nanos> nearest;
  Nanos gap{0};
  for (const TraceRecord& r : run.records) {
    if (r.connection != e.connection || r.kind != TraceKind::Deliver) continue;
    Nanos d = r.t < e.from ? e.from - r.t : r.t - e.to;
    if (!nearest || d < gap) nearest = r.t, gap = d;
  }
  std::string out = "but " + e.connection + " delivered nothing " + window(e);
  if (nearest) out += "; it delivered at " + duration_literal(*nearest);
  return out;
}

std::string check_delivers(const model::Expectation& e, const TestRun& run) {
  for (const TraceRecord& r : run.records) {
    if (r.connection == e.connection && r.kind == TraceKind::Deliver && in_window(r.t, e))
      return check_delivers(e, &r, run);
  }
  return check_delivers(e, nullptr, run);
}

std::string check_property(const model::Expectation& e, const TestRun& run) {
  std::optional<PropertyBreach> b = property_breach(e, run);
  return b ? "but " + b->what : "";
}

// The (port, event) pairs present at t, each in its port's container (after the messages of
// that instant), read off the run report's timelines, which are in seconds (exact for instants
// under 2^22 s).
std::set<std::pair<std::string, std::string>> present_at(const TestRun& run, Nanos instant) {
  double t = seconds_of(instant);
  report::RunTimeline timeline =
      report::build_run_timeline({}, run.records, std::numeric_limits<double>::infinity());
  std::set<std::pair<std::string, std::string>> out;
  for (const report::EventLane& lane : timeline.events) {
    for (const report::Interval& i : lane.present) {
      if (i.begin <= t && t < i.end) out.insert({lane.port, lane.event});
    }
  }
  return out;
}

// Each event is read in the container lowering chose for it (Expectation::containers): the
// same name in another port's container is another fact, and reading "any container" made an
// expectation pass that the port's own rules never saw (issue 38).
std::string check_state(const model::Expectation& e, const TestRun& run) {
  std::set<std::pair<std::string, std::string>> present = present_at(run, e.from);
  std::set<std::string> read;
  for (const auto& [event, port] : e.containers)
    if (present.count({port, event})) read.insert(event);
  if (evaluate(e.state, read)) return "";
  std::string out = "but at " + duration_literal(e.from);
  for (const auto& [event, port] : e.containers) {
    out += (&event == &e.containers.begin()->first ? " " : "; ") + event + " is " +
           (read.count(event) ? "present in " : "absent from ") + port + "'s container";
    std::vector<std::string> elsewhere;
    for (const auto& [p, ev] : present)
      if (ev == event && p != port) elsewhere.push_back(p);
    if (!elsewhere.empty() && !read.count(event)) {
      out += " (present in the container of ";
      for (const std::string& p : elsewhere) out += (&p == &elsewhere.front() ? "" : ", ") + p;
      out += ", another fact)";
    }
  }
  return out;
}

std::string describe(const TraceRecord& r) {
  switch (r.kind) {
    case TraceKind::Publish:
      return "publish " + r.port;
    case TraceKind::Deliver:
      return "deliver " + r.connection + " -> " + r.port;
    case TraceKind::Drop:
      return "drop " + r.connection + " (" + drop_reason_name(r.reason) + ")" +
             (r.text.empty() ? "" : ": " + r.text);
    case TraceKind::Event:
      return "event " + r.op + " " + r.event + " at " + r.port + " by " + r.owner;
    case TraceKind::Error:
      return "error " + r.connection + ": " + r.text;
    default:
      return r.connection + " " + r.text;
  }
}

}  // namespace

bool near_equal(const Value& a, const Value& b) {
  if (a.is_number() && b.is_number()) {
    // Two ints exactly (a double holds only 53 bits of them); a NaN matches only a NaN and an
    // infinity only the same infinity (within 1e-9 of inf is every number, and NaN != NaN).
    if (a.kind() == Value::Kind::Int && b.kind() == Value::Kind::Int)
      return a.as_int() == b.as_int();
    double x = a.as_float(), y = b.as_float();
    if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y);
    if (std::isinf(x) || std::isinf(y)) return x == y;
    return std::abs(x - y) <= 1e-9 * std::max({1.0, std::abs(x), std::abs(y)});
  }
  if (a.kind() != b.kind()) return false;
  switch (a.kind()) {
    case Value::Kind::Vec3:
      for (int i = 0; i < 3; ++i) {
        if (!near_equal(Value(a.as_vec3()[i]), Value(b.as_vec3()[i]))) return false;
      }
      return true;
    case Value::Kind::List:
      if (a.size() != b.size()) return false;
      for (size_t i = 0; i < a.size(); ++i) {
        if (!near_equal(a[i], b[i])) return false;
      }
      return true;
    case Value::Kind::Record:
      if (a.size() != b.size()) return false;
      for (const auto& [name, v] : a.as_record()) {
        if (!b.has(name) || !near_equal(v, b[name])) return false;
      }
      return true;
    default:
      return a == b;
  }
}

// `expect PROPERTY;`: the property over the whole run, judged as the runtime checks would.
std::optional<PropertyBreach> property_breach(const model::Expectation& e, const TestRun& run) {
  if (!e.property || !run.app) return std::nullopt;  // sema reported the property's port
  PropertyWatch watch(*e.property, rules_into(*run.app, e.property->port));
  for (const TraceRecord& r : run.records) watch.observe(r);
  watch.finish(run.end);
  return watch.breach();
}

std::pair<Nanos, Nanos> failure_window(const model::Expectation& e, const TestRun& run) {
  if (e.kind == model::Expectation::Kind::Property) {
    if (std::optional<PropertyBreach> b = property_breach(e, run)) return {b->from, b->t};
  }
  if (e.kind == model::Expectation::Kind::Exclusive || e.kind == model::Expectation::Kind::Assert ||
      e.kind == model::Expectation::Kind::Resource) {
    if (std::optional<ClaimBreach> b = claim_breach(e, run)) return {b->t, b->t};
  }
  return {e.from, e.to};
}

std::string check_expectation(const model::Expectation& e, const TestRun& run) {
  switch (e.kind) {
    case model::Expectation::Kind::Receives:
    case model::Expectation::Kind::Nothing:
      return check_receives(e, run);
    case model::Expectation::Kind::Drops:
      return check_drops(e, run);
    case model::Expectation::Kind::Delivers:
    case model::Expectation::Kind::DeliversNothing:
      return check_delivers(e, run);
    case model::Expectation::Kind::Property:
      return check_property(e, run);
    case model::Expectation::Kind::State:
      return check_state(e, run);
    case model::Expectation::Kind::Exclusive:
    case model::Expectation::Kind::Assert:
    case model::Expectation::Kind::Resource:
      if (std::optional<ClaimBreach> b = claim_breach(e, run)) return "but " + b->what;
      return "";
  }
  return "";
}

std::string trace_around(const TestRun& run, Nanos from, Nanos to) {
  const Nanos half_second = std::chrono::milliseconds(500);
  Nanos lo = from - half_second, hi = (to == kNever ? run.end : to) + half_second;
  // The runtime notices an expiry when it next looks at the container, so the trace records
  // it late, stamped with the time it happened: in time order the excerpt reads as it ran.
  std::vector<const TraceRecord*> window;
  for (const TraceRecord& r : run.records) {
    if (r.t >= lo && r.t <= hi) window.push_back(&r);
  }
  std::stable_sort(window.begin(), window.end(),
                   [](const TraceRecord* a, const TraceRecord* b) { return a->t < b->t; });
  size_t shown = std::min<size_t>(window.size(), 20), more = window.size() - shown;
  // The times in a column as wide as the widest (they read "0s", "100ms", "1.2s").
  size_t width = 0;
  for (size_t i = 0; i < shown; ++i) width = std::max(width, duration_literal(window[i]->t).size());
  std::string out;
  for (size_t i = 0; i < shown; ++i) {
    std::string t = duration_literal(window[i]->t);
    out += "    " + t + std::string(width - t.size() + 2, ' ') + describe(*window[i]) + "\n";
  }
  if (more) out += "    ... " + std::to_string(more) + " more\n";
  return out.empty() ? "    (no trace records then)\n" : out;
}

}  // namespace arbc::harness
