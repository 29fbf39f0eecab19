// The end of `arbc run`: what it prints (the run line, a row of counters per connection, the
// environment's summary, the verdict) and the report it writes, for a run that returned, and
// for one whose executor thread is stuck after an interrupt (cli/run_interrupt.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "report/report_file.h"
#include "runtime/claim_watch.h"
#include "runtime/runtime.h"

namespace arbc::cli {

struct RunEnd {
  const model::App& app;
  Runtime& runtime;
  const RunOptions& options;
  const std::vector<TraceRecord>& records;  // the trace in memory (with --report)
  const std::string& report_path;           // empty: no report
  report::ReportFile& report_file;
  const std::string& proof;  // "verified: ..." or "not verified (--no-verify)", for the report
  std::string placement;     // "dds (domain 7, ...)" (cli/run_transport.h); "" in-process
  // Not empty: what the stand-ins received (cli/run_stand_ins.h), printed after the
  // environment's summary and shown with it in the report.
  std::function<std::string()> stand_ins = {};
  // Not null: the runtime checks that watched the run (runtime/claim_watch.h).
  ClaimWatch* claims = nullptr;
  bool claims_fail = false;  // --runtime-checks fail: a violation fails the run (exit 3)
};

// After runtime.run() returned: prints everything and writes the report. `signal` names the
// signal that interrupted the run ("" for none). Returns the exit code.
int finish_run(const RunEnd& end, const std::string& signal);

// On the watchdog thread, when the run did not return `waited` seconds after `signal`: names
// the callback still running (past its wall-clock budget, for a monitor), prints the counters
// as they are, closes the trace and writes the report of an interrupted run. Nothing here calls
// plugin code (the environment may be what is stuck). The caller then ends the process.
void give_up_stuck_run(const RunEnd& end, const std::string& signal, double waited);

}  // namespace arbc::cli
