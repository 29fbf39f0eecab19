// `arbc import yarp APP.xml -o app.spec`: the imported application as a spec
// (docs/yarp.md#moving-to-a-spec). Every monitored connection becomes a rule (or `connect`)
// whose body is `script "<the original Lua file>";`, with the constraint YARP selects on, so a
// team can replace the scripts by spec bodies one at a time. YARP port names become
// `Module.port` (the last part of the name is the port, the rest the module), listed in a
// comment at the top; all ports carry `Bottle`, declared as a list of strings.
#pragma once

#include <string>
#include <vector>

#include "import/yarp/yarp_import.h"

namespace arbc::yarp {

// The spec text. `spec_path` is where it will be written: `script` paths are made relative to
// its folder. Modules, ports of a module and rules into a port whose YARP names become one
// spec name are told apart, each renamed one with a warning in `renamed` (spec_names.h).
std::string write_spec(const YarpImport& im, const std::string& spec_path,
                       std::vector<Diagnostic>& renamed);

}  // namespace arbc::yarp
