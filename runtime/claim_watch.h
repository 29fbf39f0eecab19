// What a run checks of what `arbc verify` proved and assumed (issue 39): fed every trace record
// as the runtime makes it, it watches
//   - each property over time of the app (runtime/property_watch.h): a declared property is a
//     claim (build refuses one the proof refutes), so a breach means the run left what was
//     proved;
//   - the assumptions the proofs rest on, at every decision of a rule, in the state of the
//     rule's port: `exclusive` groups, `invariant`s, environment assumptions (`assume ...`),
//     and source rates (`given M.p every D`: the source published at least every D from the
//     start).
// Each claim or assumption is reported once, at the first instant a run breaks it: from there
// on the proof no longer covers the run.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/instant.h"
#include "runtime/property_watch.h"
#include "runtime/trace_container.h"
#include "runtime/trace_record.h"

namespace arbc {

struct ClaimViolation {
  Nanos t{0};
  std::string claim;  // as the spec writes it: "never two take within 1s", "exclusive { a, b }"
  std::string what;   // what the run did
  bool assumption = false;  // an assumption broke (not a claim)
};

class ClaimWatch {
 public:
  explicit ClaimWatch(const model::App& app);

  // Whether the app states anything to watch (a run without claims pays nothing).
  bool empty() const;
  // How many claims and assumptions it watches.
  size_t size() const;
  void observe(const TraceRecord& r);
  // The run ended at `end` (response windows and rates up to there are judged).
  void finish(Nanos end);
  // The first violation of each claim and assumption, in the order they happened.
  const std::vector<ClaimViolation>& violations() const { return violations_; }

 private:
  struct Assumed {
    const model::Assumption* a;
    bool armed = false;
    std::optional<Nanos> last_after;
  };
  struct Rate {
    const model::SourceRate* r;
    Nanos last{0};  // the start counts: `given` says "from the start"
  };

  void decision(const std::string& port, Nanos t, const std::set<std::string>& state);
  void assumption(Assumed& s, const std::string& port, const TraceRecord& r,
                  const std::set<std::string>& state);
  void rate_gaps(Nanos t);
  void violated(const std::string& claim, Nanos t, std::string what, bool assumption);

  const model::App& app_;
  std::vector<std::unique_ptr<PropertyWatch>> properties_;
  std::vector<std::string> property_text_;
  std::vector<Assumed> assumed_;
  std::vector<Rate> rates_;
  std::map<std::string, std::string> rule_port_;  // rule -> its arbitrated port
  std::map<std::string, TraceContainer> boxes_;   // arbitrated port -> its container
  std::set<std::string> reported_;
  std::vector<ClaimViolation> violations_;
};

}  // namespace arbc
