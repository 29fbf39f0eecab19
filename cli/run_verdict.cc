#include "cli/run_verdict.h"

#include "core/duration_literal.h"
#include "core/join.h"

namespace arbc::cli {

RunVerdict judge_by_environment(bool environment_success) {
  return {environment_success, environment_success ? "success" : "failure"};
}

RunVerdict judge_without_environment(const std::vector<ConnectionStats>& connections,
                                     const std::vector<InputStats>& inputs) {
  std::vector<std::string> broken;
  for (const ConnectionStats& s : connections) {
    if (s.quarantined) broken.push_back(s.name + " quarantined");
    if (uint64_t n = s.drops(DropReason::BadType))
      broken.push_back(std::to_string(n) + " bad-type into " + s.name);
  }
  for (const InputStats& s : inputs) {
    if (uint64_t n = s.drops(DropReason::BadType))
      broken.push_back(std::to_string(n) + " bad-type into " + s.port);
  }
  bool success = broken.empty();
  std::string text = std::string(success ? "success" : "failure") +
                     " (no environment; judged by quarantined connections and messages of the "
                     "wrong type";
  return {success, text + (broken.empty() ? "" : ": " + join(broken, ", ")) + ")"};
}

std::string broken_claim_name(const ClaimViolation& v) {
  return (v.assumption ? "assumption " : "") + v.claim;
}

RunVerdict with_broken_claims(RunVerdict verdict, const std::vector<ClaimViolation>& broken,
                              bool fail) {
  if (broken.empty() || !fail) return verdict;
  std::vector<std::string> names;
  for (const ClaimViolation& v : broken)
    names.push_back(broken_claim_name(v) + " at " + duration_literal(v.t));
  // A run already failed keeps its reason after the checks' ("success" has nothing to keep).
  bool kept = verdict.text.rfind("success", 0) != 0;
  return {false, "failure (runtime checks: " + join(names, "; ") + " broken" +
                     (kept ? "; " + verdict.text : "") + ")"};
}

}  // namespace arbc::cli
