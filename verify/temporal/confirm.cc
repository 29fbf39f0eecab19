#include "verify/temporal/confirm.h"

#include "verify/temporal/assumption.h"
#include "verify/temporal/judge.h"
#include "verify/temporal/property.h"

namespace arbc::verify::temporal {
namespace {

Finding internal_replay_error(const TemporalResult& r, const std::string& what) {
  Finding f;
  f.check = kCheckInternal;
  f.severity = Severity::Error;
  f.port = r.property.port;
  if (!r.property.rule.empty()) f.rules = {r.property.rule};  // a stability names none
  if (!r.property.other.empty()) f.rules.push_back(r.property.other);
  f.loc = r.property.loc;
  f.message = "internal error: the model checker and the runtime disagree on `" +
              property_words(r.property) + "`: " + what + "; please report this bug";
  return f;
}

void unknown(TemporalResult& r, const std::string& why) {
  r.outcome = TemporalResult::Outcome::Unknown;
  r.unknown_reason = why;
}

}  // namespace

Confirmation confirm_violation(const TestReplayer* replayer, TemporalResult& r,
                               std::vector<Finding>& findings, std::string* seen) {
  if (r.outcome != TemporalResult::Outcome::Violated) return Confirmation::Shown;
  if (!r.replay_test) {
    unknown(
        r, "violated in the abstract model, but the trace cannot be replayed: " + r.not_replayable);
    return Confirmation::NotReplayed;
  }
  if (!replayer) {
    unknown(r, "violated in the abstract model, not replayed (no runtime)");
    return Confirmation::NotReplayed;
  }
  std::string err;
  std::optional<std::vector<ReplayRecord>> records =
      replayer->replay(*r.replay_test, r.property.port, &err);
  if (!records) {
    findings.push_back(internal_replay_error(r, "the replay did not run (" + err + ")"));
    unknown(r, "internal error in the replay");
    return Confirmation::NotReplayed;
  }
  for (const model::Assumption& a : r.assumptions) {
    std::string broken;
    if (!replay_respects(a, *records, &broken)) {
      *seen = "the replay breaks the assumption `" + model::assumption_text(a) + "`: " + broken;
      return Confirmation::NotShown;
    }
  }
  if (!replay_violates(r.property, *records, seen)) {
    *seen = "replayed, " + *seen;
    return Confirmation::NotShown;
  }
  r.replayed = true;
  return Confirmation::Shown;
}

}  // namespace arbc::verify::temporal
