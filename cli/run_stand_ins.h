// `arbc run`'s options for trying a spec without C++ (docs/testing.md): --inputs FILE, --stub,
// --stub-rate PORT=HZ and --diff OTHER_TRACE. With --inputs or --stub, every module of the app
// that no plugin provides runs as a stand-in (runtime/stand_in.h); without them a missing
// module is an error, as before.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "runtime/runtime.h"
#include "runtime/stand_in.h"

namespace arbc::cli {

// The highest --stub-rate (a period of one microsecond), and the most samples the stand-ins may
// publish in one run (a few minutes of work for the simulated executor).
inline constexpr double kMaxStubHz = 1e6;
inline constexpr double kMaxStubSamples = 1e8;

class RunStandIns {
 public:
  void add_options(CLI::App& cli);
  // Any of the options given: stand-ins run.
  bool active() const { return !inputs_.empty() || stub_; }
  bool wants_records() const { return !diff_.empty(); }
  // The registry the run uses: the global one, plus stand-ins when active(). Reads and checks
  // the inputs file, and the other trace for --diff. False with *err (bad input).
  // `duration` is the run's length in seconds, which bounds what --stub publishes.
  bool prepare(const model::App& app, double duration, std::string* err);
  Registry& registry() { return registry_; }
  // What each stand-in received and published ("" when none ran).
  std::string summary(const model::App& app) const;
  // After the run, with --diff: prints the first difference from the other trace. Returns the
  // exit code to use: `run_exit` when the runs agree or it is already a failure, else 1.
  int diff(const model::App& app, const std::vector<TraceRecord>& records, int run_exit) const;

 private:
  bool parse_rates(std::string* err);
  bool check_sample_budget(const model::App& app, double duration, std::string* err);
  std::string inputs_, diff_;
  bool stub_ = false;
  std::vector<std::string> rates_;
  std::shared_ptr<StandInLog> log_ = std::make_shared<StandInLog>();
  std::vector<std::string> stand_ins_;
  std::vector<TraceRecord> other_;
  Registry registry_;
};

}  // namespace arbc::cli
