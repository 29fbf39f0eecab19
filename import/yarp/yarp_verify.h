// `arbc verify APP.xml`: a yarpmanager application and its Lua monitors, imported with
// import/yarp/yarp_import.h and proved like a spec
// (docs/yarp.md#verifying-an-existing-application). The YARP hazards join the report as findings;
// each exclusivity counterexample gets a note at the Lua line where each rule's constraint is set.
#pragma once

#include <string>
#include <vector>

#include "verify/report.h"
#include "verify/verify.h"

namespace arbc::yarp {

// Does the command line name a yarpmanager application (*.xml)?
bool is_yarp_application(const std::string& input);

struct YarpVerify {
  bool ok = false;          // false: bad input; `diagnostics` says why
  std::string diagnostics;  // rendered problems with the input, for stderr
  verify::VerifyReport report;
};

YarpVerify verify_yarp_application(const std::string& xml, const verify::VerifyOptions& options,
                                   const std::vector<std::string>& search_paths);

}  // namespace arbc::yarp
