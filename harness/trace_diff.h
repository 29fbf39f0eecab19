// `arbc run --inputs TRACE --diff OTHER_TRACE`: where two runs' decisions differ
// (docs/testing.md#replaying-a-recorded-run). A decision is what a connection did with one
// message: delivered it, or dropped it with a reason. The k-th message on a connection in one
// run is compared with the k-th in the other; the first difference (the earliest in time) is
// shown with the destination's event state, in each run, just before that decision.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "runtime/trace_record.h"

namespace arbc::harness {

// Reads a trace written by `arbc run --trace` into records (values are not kept). False with
// *err naming the file and line on a line that is not a trace record.
bool read_trace_file(const std::string& path, std::vector<TraceRecord>* records, std::string* err);

// The decisions of `now` (this run) and `before` (OTHER_TRACE), compared. Empty when every
// connection decided the same, at the same times; else a few lines about the first difference.
std::string first_difference(const model::App& app, const std::vector<TraceRecord>& now,
                             const std::vector<TraceRecord>& before,
                             const std::string& before_name);

}  // namespace arbc::harness
