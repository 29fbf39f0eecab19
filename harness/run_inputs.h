// `arbc run --inputs FILE`: timed messages for the out-ports of the modules no plugin provides
// (docs/testing.md#scripted-inputs---inputs). FILE is JSON Lines: input lines
//   {"t": 1.25, "port": "FaceDetector.face", "value": {...}}
// or a trace written by `arbc run --trace`, whose `publish` lines are replayed (its other lines
// are what that run did, not inputs). Every line is checked against the app before the run.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "runtime/stand_in.h"

namespace arbc::harness {

struct InputsRead {
  size_t messages = 0;          // scheduled on stand-ins
  size_t skipped_provided = 0;  // trace lines of modules a plugin provides (they publish anew)
  bool from_trace = false;
};

// Reads `path` into log's inputs (StandInLog::add_input: in time order, the lines of one instant
// in the file's order). False with *err
// ("FILE:LINE: field 'value': field pos.y: expected float, got string") on the first bad line:
// not JSON, no or a negative `t`, a port that is not an out-port of the app, a module a plugin
// provides (in an input line), a value that does not fit the port's type.
bool read_inputs(const std::string& path, const model::App& app,
                 const std::vector<std::string>& stand_ins, StandInLog* log, InputsRead* read,
                 std::string* err);

}  // namespace arbc::harness
