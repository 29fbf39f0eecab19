// A monitor that does not require("yarp") when it loads: YARP 3.12 hands create, accept,
// update (and update_reply, setparam, getparam) a YARP object through SWIG, whose types exist
// in the monitor's Lua state only once the bindings are loaded; without them the receiving
// process crashes (segmentation fault) when the connection is made or the first message
// arrives (docs/yarp.md#yarp-require, YarpApp.MonitorWithoutRequireCrashesTheReceiver).
#pragma once

#include <vector>

#include "core/diagnostic.h"
#include "import/yarp/yarp_import.h"

namespace arbc::yarp {

// Adds a yarp-require error to `out` when the connection's monitor loaded without calling
// require("yarp") and defines a callback YARP calls with a YARP object.
void check_requires_yarp(const ImportedConnection& ic, std::vector<Diagnostic>& out);

}  // namespace arbc::yarp
