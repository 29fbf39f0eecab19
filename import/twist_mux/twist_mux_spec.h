// A twist_mux configuration as a spec and a DDS deployment (`arbc import twist_mux`,
// docs/twist_mux.md): each input a rule into Base.cmd_vel, active for its timeout after each of
// its messages; each lock an event that blocks the rules below its priority, engaged by `true`
// and, with a timeout, by silence. What twist_mux decides without saying (a tie between two
// inputs, an input it never publishes) is a warning at the YAML's line.
#pragma once

#include <string>
#include <vector>

#include "core/diagnostic.h"
#include "import/twist_mux/twist_mux_config.h"

namespace arbc::twist_mux {

struct MuxSpec {
  std::string spec;    // the app, its properties and its tests
  std::string deploy;  // the deployment file: ROS 2 names of each module's topic
  std::vector<Diagnostic> warnings;
};

// `output_topic`: where twist_mux publishes (its `cmd_vel_out`, usually remapped).
MuxSpec write_mux_spec(const MuxConfig& config, const std::string& source_name,
                       const std::string& output_topic);

}  // namespace arbc::twist_mux
