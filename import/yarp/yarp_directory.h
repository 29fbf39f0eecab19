// A directory given where arbc expects an app directory (its app.json) may be a build for YARP
// (`arbc build --target yarp`: DIR/<app>.xml, ports.json, contexts/) or a folder that holds a
// yarpmanager application. `arbc verify DIR` proves the former's application XML, and says
// which XML to give for the latter, instead of "cannot read DIR/app.json".
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace arbc::yarp {

struct YarpDirectory {
  std::optional<std::string> build_xml;  // DIR/<app>.xml of a --target yarp build (ports.json)
  std::vector<std::string> xmls;         // every DIR/*.xml, sorted, when DIR has no app.json
};

// What `path` holds, if it is a directory without an app.json; empty otherwise.
YarpDirectory yarp_directory(const std::string& path);

}  // namespace arbc::yarp
