#include "verify/temporal/confirm.h"

#include "core/instant.h"
#include "core/join.h"
#include "core/time_text.h"

namespace arbc::verify::temporal {
namespace {

Finding internal_replay_error(const TemporalResult& r, const std::string& what) {
  Finding f;
  f.check = kCheckInternal;
  f.severity = Severity::Error;
  f.port = r.property.port;
  f.rules = {r.property.rule};
  f.loc = r.property.loc;
  f.message = "internal error: the model checker and the runtime disagree on `never two " +
              r.property.rule + " within " + time_text(r.property.window) + "s`: " + what +
              "; please report this bug";
  return f;
}

void unknown(TemporalResult& r, const std::string& why) {
  r.outcome = TemporalResult::Outcome::Unknown;
  r.unknown_reason = why;
}

}  // namespace

bool spaced_less_than(const std::vector<double>& times, double window) {
  for (size_t i = 1; i < times.size(); ++i)
    if (!reached(times[i] - times[i - 1], window)) return true;
  return false;
}

void confirm_violation(const TestReplayer* replayer, TemporalResult& r,
                       std::vector<Finding>& findings) {
  if (r.outcome != TemporalResult::Outcome::Violated) return;
  if (!r.replay_test) {
    unknown(
        r, "violated in the abstract model, but the trace cannot be replayed: " + r.not_replayable);
    return;
  }
  if (!replayer) {
    unknown(r, "violated in the abstract model, not replayed (no runtime)");
    return;
  }
  std::string err;
  std::optional<std::vector<double>> times =
      replayer->deliveries(*r.replay_test, r.property.rule, &err);
  if (!times) {
    findings.push_back(internal_replay_error(r, "the replay did not run (" + err + ")"));
    unknown(r, "internal error in the replay");
    return;
  }
  if (!spaced_less_than(*times, r.property.window)) {
    std::vector<std::string> at;
    for (double t : *times) at.push_back(time_text(t) + "s");
    findings.push_back(
        internal_replay_error(r, "replayed, '" + r.property.rule + "' delivered at " +
                                     (at.empty() ? std::string("no time") : join(at))));
    unknown(r, "internal error in the replay");
    return;
  }
  r.replayed = true;
}

}  // namespace arbc::verify::temporal
