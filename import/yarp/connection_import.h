// Imports one <connection>: parses its carrier, finds and analyses its Lua monitor, and works
// out its constraint as YARP evaluates it. Internal to yarp_import.h.
#pragma once

#include <string>
#include <vector>

#include "import/yarp/yarp_import.h"

namespace arbc::yarp {

// Problems go to `out`; a monitor that cannot be found sets `bad_input`. A connection whose
// monitor cannot be analysed comes back with analysed == false (always selected, opaque).
ImportedConnection import_connection(const XmlConnection& xml, const std::string& xml_file,
                                     const YarpImportOptions& options, YarpEvaluator& evaluator,
                                     std::vector<Diagnostic>& out, bool& bad_input);

}  // namespace arbc::yarp
