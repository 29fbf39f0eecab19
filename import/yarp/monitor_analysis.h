// Everything arbc learns about one connection's Lua monitor: its text read (script_facts.h),
// its create and accept run on samples (script_runner.h), and the constraint it ends up with.
#pragma once

#include <optional>
#include <set>
#include <string>

#include "core/app_model.h"
#include "import/yarp/carrier.h"
#include "import/yarp/script_facts.h"
#include "import/yarp/script_runner.h"

namespace arbc::yarp {

struct MonitorAnalysis {
  std::string path;  // the script file
  std::string text;
  bool parsed = false;      // arbc's Lua parser read it (else facts are opaque)
  std::string parse_error;  // when not
  ScriptFacts facts;
  ScriptRun run;
  // The constraint YARP would hold after create: setConstraint in create, else the carrier's
  // +constraint.WORD, else none ("": every message passes).
  std::string constraint;
  bool has_constraint = false;
  model::SourceLocation constraint_loc;                  // the setConstraint call, or the carrier
  std::set<std::string> observed_sets, observed_unsets;  // on the sample bottles
};

// Analyses the script at `path` (already read into `text`) for the connection `context`.
// `carrier_loc` locates the carrier string, for a constraint given there.
MonitorAnalysis analyse_monitor(const std::string& path, const std::string& text,
                                const MonitorContext& context, const Carrier& carrier,
                                const model::SourceLocation& carrier_loc);

}  // namespace arbc::yarp
