// A twist_mux parameter file as twist_mux reads it (docs/twist_mux.md): velocity inputs and Bool
// locks, each a topic, a timeout and a priority. Both forms are read: ROS 2's
// `NODE: ros__parameters: topics: NAME: {topic, timeout, priority}` (and `locks:`), and ROS 1's
// `topics:` list of `{name, topic, timeout, priority}`. Several files (twist_mux ships its
// topics and locks apart) make one configuration.
#pragma once

#include <string>
#include <vector>

#include "core/diagnostic.h"

namespace arbc::twist_mux {

struct MuxEntry {
  std::string name;    // the key (ROS 2) or `name:` (ROS 1)
  std::string topic;   // as written: relative names are in twist_mux's namespace
  double timeout = 0;  // seconds; 0 (or below): never expires
  int priority = 0;    // 0..255, clamped as twist_mux clamps it
  bool lock = false;
  model::SourceLocation loc;           // the entry's name
  model::SourceLocation priority_loc;  // its priority value
};

struct MuxConfig {
  bool ok = false;
  std::vector<MuxEntry> inputs, locks;  // in the files' order
  std::vector<Diagnostic> diagnostics;  // errors (then !ok) and warnings, with file and line
};

// Reads `files` in order; a file that cannot be read, is not YAML or not twist_mux's shape is an
// error at its line. No input at all is an error too.
MuxConfig read_twist_mux(const std::vector<std::string>& files);
// The same for one text, `file` naming it in diagnostics (for tests).
void read_twist_mux_text(const std::string& text, const std::string& file, MuxConfig& into);

}  // namespace arbc::twist_mux
