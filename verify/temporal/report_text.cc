#include "verify/temporal/report_text.h"

#include <cstdio>

#include "core/join.h"
#include "core/time_text.h"

namespace arbc::verify::temporal {
namespace {

// What "holds up to the bound" assumes, printed with every verdict.
constexpr const char* kAssumptions =
    "    assuming: sources publish at any times; monitors accept or reject any message (data is\n"
    "    not modelled); exclusive groups and invariants are not used\n";

std::string property_text(const model::TemporalProperty& p) {
  std::string where = p.loc.line ? " (" + p.loc.file + ":" + std::to_string(p.loc.line) + ")" : "";
  return "never two " + p.rule + " within " + time_text(p.window) + "s" + where;
}

// "    at 0.25s  ObjectDetector.objects -> take: accepted, delivered; sets e_x"
std::string step_text(const TraceStep& s) {
  char time[32];
  std::snprintf(time, sizeof time, "%-8s", (time_text(s.time) + "s").c_str());
  std::string line = "    at " + std::string(time) + " " + s.source + " -> " + s.connection + ": ";
  line += s.feed        ? "feed"
          : s.delivered ? "accepted, delivered"
          : s.accepted  ? "accepted, not delivered"
                        : "rejected";
  if (!s.set.empty()) line += "; sets " + join(s.set);
  if (!s.unset.empty()) line += "; unsets " + join(s.unset);
  return line + "\n";
}

}  // namespace

std::string temporal_text(const TemporalResult& r) {
  const std::string port = r.property.port;
  std::string out = "  " + property_text(r.property) + ": ";
  std::string messages = std::to_string(r.bound) + " message" + (r.bound == 1 ? "" : "s");
  switch (r.outcome) {
    case TemporalResult::Outcome::HoldsToBound:
      out += "holds up to " + messages + " into " + port + " (bounded; not proved)\n";
      break;
    case TemporalResult::Outcome::Unknown:
      out += "unknown (" + r.unknown_reason + ") after " + messages + " into " + port + "\n";
      break;
    case TemporalResult::Outcome::Violated:
      out += "violated in the abstract model: a shortest trace of " + messages + " into " + port +
             " (not replayed on the runtime):\n";
      for (const TraceStep& s : r.trace) out += step_text(s);
      break;
  }
  return out + kAssumptions;
}

}  // namespace arbc::verify::temporal
