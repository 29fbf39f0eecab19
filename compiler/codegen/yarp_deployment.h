// The deployment file of the yarp target (docs/yarp.md#names-on-yarp): the DDS transport's
// JSON, of which the yarp target reads `"topics": {"Module.port": "/yarp/name", ...}` to name
// YARP ports; its other keys (domain, ros2, types) are the DDS transport's and are ignored.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "core/app_model.h"

namespace arbc::codegen {

// Reads `path`: the port-name overrides, checked against `app` (each key a port of the spec,
// each name a YARP port name: '/' first, no blank, no two ports alike). nullopt and `err`
// (naming the file and what to change) otherwise.
std::optional<std::map<std::string, std::string>> read_yarp_deployment(const std::string& path,
                                                                       const model::App& app,
                                                                       std::string* err);

}  // namespace arbc::codegen
