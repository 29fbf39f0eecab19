// The yarpmanager application and the port map of a YARP deployment
// (docs/yarp.md#deploying-a-spec-on-yarp-step-by-step).
#pragma once

#include <string>

#include "compiler/codegen/yarp_names.h"
#include "core/app_model.h"

namespace arbc::codegen {

// `<app>.xml`: one <module> per spec module, a placeholder the user completes (the executable,
// its parameters, the node), and one <connection> per YARP link, with its portmonitor carrier
// (`+context.<app>`: the monitors are found in contexts/<app>/ of YARP's data folders).
std::string yarp_application_xml(const model::App& app, const YarpNames& names);

// `ports.json`: each spec port's YARP name and type, each YARP connection with its monitor and
// the spec connections it carries, and each YARP event name with what it stands for.
std::string yarp_port_map(const model::App& app, const YarpNames& names);

// The folder (relative to the app directory) and the carrier of a link's monitor.
std::string yarp_monitor_path(const model::App& app, const YarpLink& link);
std::string yarp_carrier(const model::App& app, const YarpLink& link);

}  // namespace arbc::codegen
