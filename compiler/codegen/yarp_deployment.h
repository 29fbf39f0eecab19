// The deployment file of the yarp target (docs/yarp.md#names-on-yarp): the DDS transport's
// JSON, of which the yarp target reads `"topics": {"Module.port": "/yarp/name", ...}` to name
// YARP ports; its other keys (domain, ros2, types, qos) are the DDS transport's and are
// ignored, and any other key is an error (a misspelt "topics" would rename nothing).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/diagnostic.h"

namespace arbc::codegen {

// Reads `path`: the port-name overrides, checked against `app` (each key a port of the spec,
// each name a YARP port name: '/' first, no blank, no two ports alike). nullopt and *errors
// otherwise: one per problem, at the line and column of its key or value (of the offending
// character when the file is not JSON), saying what to change.
std::optional<std::map<std::string, std::string>> read_yarp_deployment(
    const std::string& path, const model::App& app, std::vector<Diagnostic>* errors);

}  // namespace arbc::codegen
