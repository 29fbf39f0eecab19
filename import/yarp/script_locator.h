// Finds the Lua file a portmonitor carrier names, the way YARP's ResourceFinder would from the
// receiving process, with the folders arbc can know about (docs/yarp.md#finding-the-monitors):
//   each --yarp-path DIR:   DIR/contexts/CTX/ (with +context.CTX), then DIR/
//   the XML's folder:       the same two places
//   $YARP_DATA_HOME, then each of $YARP_DATA_DIRS (':'-separated): the same two places
// In each place NAME is tried as given, then NAME.lua (as YARP does).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace arbc::yarp {

struct ScriptLookup {
  std::optional<std::string> found;  // the path of the file
  std::vector<std::string> tried;    // every path tried, in order (for the error message)
};

ScriptLookup locate_script(const std::string& name, const std::string& context,
                           const std::string& xml_file,
                           const std::vector<std::string>& search_paths);

}  // namespace arbc::yarp
