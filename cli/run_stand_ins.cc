#include "cli/run_stand_ins.h"

#include <cstdio>
#include <cstdlib>

#include "cli/commands.h"
#include "harness/out_port_hint.h"
#include "harness/run_inputs.h"
#include "harness/trace_diff.h"

namespace arbc::cli {

void RunStandIns::add_options(CLI::App& cli) {
  cli.add_option("--inputs", inputs_,
                 "JSON lines of timed messages (or a trace) for modules no plugin provides");
  cli.add_flag("--stub", stub_,
               "run modules no plugin provides as stand-ins publishing typed samples (10 Hz)");
  cli.add_option("--stub-rate", rates_, "PORT=HZ: a stand-in port's sample rate (0: silent)");
  cli.add_option("--diff", diff_, "a trace of another run: show the first differing decision");
}

bool RunStandIns::parse_rates(std::string* err) {
  for (const std::string& r : rates_) {
    size_t eq = r.find('=');
    char* end = nullptr;
    double hz = eq == std::string::npos ? -1 : std::strtod(r.c_str() + eq + 1, &end);
    if (eq == std::string::npos || !end || *end != '\0' || end == r.c_str() + eq + 1 || hz < 0) {
      *err = "--stub-rate " + r + ": expected PORT=HZ, e.g. ObjectDetector.objects=5";
      // `=10Hz`, `=100ms`: the rate is a bare number of samples per second.
      if (end && end != r.c_str() + eq + 1 && *end != '\0' && hz >= 0)
        *err += " (the rate is a plain number of samples per second: write " + r.substr(0, eq) +
                "=" +
                std::string(static_cast<const char*>(r.c_str() + eq + 1),
                            static_cast<const char*>(end)) +
                ", without '" + end + "')";
      return false;
    }
    if (hz > kMaxStubHz) {
      *err = "--stub-rate " + r + ": at most 1000000 samples per second (one per microsecond, " +
             "the shortest time arbc works with)";
      return false;
    }
    log_->stub.period_of_port[r.substr(0, eq)] = hz == 0 ? 0 : 1 / hz;
  }
  return true;
}

// Every stand-in source samples for the whole run: refused beyond kMaxStubSamples, which a run
// works through in minutes (`--stub-rate P=1e9` was accepted and ran until killed).
bool RunStandIns::check_sample_budget(const model::App& app, double duration, std::string* err) {
  double samples = 0;
  std::string busiest;
  double busiest_rate = 0;
  for (const std::string& name : stand_ins_) {
    const model::Module* m = app.find_module(name);
    for (const model::Port& p : m ? m->ports : std::vector<model::Port>{}) {
      std::string q = name + "." + p.name;
      if (p.direction != model::Direction::Out || log_->inputs_on(q)) continue;
      auto it = log_->stub.period_of_port.find(q);
      double period =
          it == log_->stub.period_of_port.end() ? log_->stub.default_period : it->second;
      if (period <= 0) continue;
      samples += duration / period;
      if (1 / period > busiest_rate) busiest_rate = 1 / period, busiest = q;
    }
  }
  if (samples <= kMaxStubSamples) return true;
  char text[160];
  std::snprintf(text, sizeof text,
                "--stub: the stand-ins would publish about %.3g samples in this run (%s at %g "
                "per second the most); at most %.0f: ",
                samples, busiest.c_str(), busiest_rate, kMaxStubSamples);
  *err = std::string(text) + "shorten --duration or lower --stub-rate";
  return false;
}

bool RunStandIns::prepare(const model::App& app, double duration, std::string* err) {
  registry_ = Registry::global();
  if (!rates_.empty() && !stub_) return *err = "--stub-rate needs --stub", false;
  if (!diff_.empty() && !harness::read_trace_file(diff_, &other_, err)) return false;
  if (!active()) return true;
  log_->stub.enabled = stub_;
  log_->keep_received = false;  // the summary needs the tallies only
  if (!parse_rates(err)) return false;
  for (const auto& [port, period] : log_->stub.period_of_port) {
    const model::Port* p = app.find_port(port);
    if (!p || p->direction != model::Direction::Out)
      return *err = "--stub-rate: " + harness::not_an_out_port(app, port), false;
  }
  registry_ = registry_with_stand_ins(app, Registry::global(), log_, &stand_ins_);
  if (inputs_.empty()) return !stub_ || check_sample_budget(app, duration, err);
  harness::InputsRead read;
  if (!harness::read_inputs(inputs_, app, stand_ins_, log_.get(), &read, err)) return false;
  if (stub_ && !check_sample_budget(app, duration, err)) return false;
  std::printf("inputs: %zu messages from %s%s", read.messages, inputs_.c_str(),
              read.from_trace ? " (a trace: its publications are replayed)" : "");
  if (read.skipped_provided)
    std::printf("; %zu of modules a plugin provides skipped", read.skipped_provided);
  std::printf("\n");
  return true;
}

std::string RunStandIns::summary(const model::App& app) const {
  return stand_in_summary(app, stand_ins_, *log_);
}

int RunStandIns::diff(const model::App& app, const std::vector<TraceRecord>& records,
                      int run_exit) const {
  if (diff_.empty()) return run_exit;
  std::string difference = harness::first_difference(app, records, other_, diff_);
  if (difference.empty()) {
    std::printf("diff: every decision is the same as in %s\n", diff_.c_str());
    return run_exit;
  }
  std::fputs(("diff: " + difference).c_str(), stdout);
  return run_exit == kExitOk ? kExitRefuted : run_exit;
}

}  // namespace arbc::cli
