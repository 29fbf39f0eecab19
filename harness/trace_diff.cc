#include "harness/trace_diff.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "core/duration_literal.h"
#include "report/run_timeline.h"
#include "runtime/trace_format.h"

namespace arbc::harness {

namespace {

using Json = nlohmann::json;

struct Decision {
  size_t index = 0;  // in the run's records
  const TraceRecord* record = nullptr;
};

std::map<std::string, std::vector<Decision>> decisions(const std::vector<TraceRecord>& records) {
  std::map<std::string, std::vector<Decision>> out;
  for (size_t i = 0; i < records.size(); ++i) {
    const TraceRecord& r = records[i];
    if (r.kind == TraceKind::Deliver || r.kind == TraceKind::Drop) {
      out[r.connection].push_back({i, &r});
    }
  }
  return out;
}

std::string describe(const TraceRecord* r) {
  if (!r) return "no such message";
  if (r->kind == TraceKind::Deliver) return "delivered";
  std::string out = std::string("dropped (") + drop_reason_name(r->reason) + ")";
  if (!r->text.empty()) out += ": " + r->text;
  return out;
}

bool same(const TraceRecord* a, const TraceRecord* b) {
  if (!a || !b) return a == b;
  return a->kind == b->kind && a->t == b->t &&
         (a->kind == TraceKind::Deliver || a->reason == b->reason);
}

// The events present in `port`'s container just before records[index] (at time t).
std::string events_before(const std::vector<TraceRecord>& records, size_t index,
                          const std::string& port, Nanos instant) {
  std::vector<TraceRecord> before(records.begin(), records.begin() + index);
  double t = seconds_of(instant);  // the timelines' seconds
  report::RunTimeline timeline =
      report::build_run_timeline({}, before, t + std::numeric_limits<double>::epsilon() * (1 + t));
  std::string out;
  for (const report::EventLane& lane : timeline.events) {
    if (lane.port != port) continue;
    for (const report::Interval& i : lane.present) {
      if (i.begin <= t && t < i.end) out += (out.empty() ? "" : ", ") + lane.event;
    }
  }
  return out.empty() ? "(none)" : out;
}

}  // namespace

bool read_trace_file(const std::string& path, std::vector<TraceRecord>* records, std::string* err) {
  std::ifstream in(path);
  if (!in) return *err = path + ": cannot read the trace: " + std::strerror(errno), false;
  std::string text;
  for (size_t line = 1; std::getline(in, text); ++line) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    TraceRecord r;
    bool ok = false;
    try {
      ok = read_trace_line(Json::parse(text), &r, nullptr);
    } catch (const Json::exception&) {  // nlohmann-json reports syntax errors by throwing
    }
    if (!ok) {
      *err = path + ":" + std::to_string(line) +
             ": not a trace record (write traces with `arbc run --trace FILE`)";
      return false;
    }
    records->push_back(std::move(r));
  }
  return true;
}

std::string first_difference(const model::App& app, const std::vector<TraceRecord>& now,
                             const std::vector<TraceRecord>& before,
                             const std::string& before_name) {
  auto a = decisions(now), b = decisions(before);
  for (const auto& [name, list] : b) a[name];  // connections only the other run has
  Nanos best_t = kNever;
  std::string best_name;
  size_t best_k = 0;
  for (const auto& [name, list] : a) {
    const std::vector<Decision>& other = b[name];
    for (size_t k = 0; k < std::max(list.size(), other.size()); ++k) {
      const TraceRecord* x = k < list.size() ? list[k].record : nullptr;
      const TraceRecord* y = k < other.size() ? other[k].record : nullptr;
      if (same(x, y)) continue;
      Nanos t = std::min(x ? x->t : best_t, y ? y->t : best_t);
      if (t < best_t) best_t = t, best_name = name, best_k = k;
      break;
    }
  }
  if (best_name.empty()) return "";
  const model::Connection* c = nullptr;
  for (const model::Connection& conn : app.connections) {
    if (conn.name == best_name) c = &conn;
  }
  std::string port = c ? c->destination : "";
  std::string out = "first difference: connection " + best_name +
                    (port.empty() ? "" : " into " + port) + ", its message " +
                    std::to_string(best_k + 1) + ", at " + duration_literal(best_t) + "\n";
  auto line = [&](const std::string& who, const std::vector<Decision>& list,
                  const std::vector<TraceRecord>& records) {
    const TraceRecord* r = best_k < list.size() ? list[best_k].record : nullptr;
    out += "  " + who + ": " + describe(r);
    if (r && r->t != best_t) out += " at " + duration_literal(r->t);
    if (r && !port.empty())
      out += "; events at " + port + ": " + events_before(records, list[best_k].index, port, r->t);
    out += "\n";
  };
  line("this run", a[best_name], now);
  line(before_name, b[best_name], before);
  return out;
}

}  // namespace arbc::harness
