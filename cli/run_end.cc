#include "cli/run_end.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli/run_verdict.h"
#include "core/duration_literal.h"
#include "core/time_format.h"
#include "report/run_report.h"

namespace arbc::cli {

namespace {

// The report's input: the header as `arbc run` prints it, the counters, the trace records.
// `environment` is the environment's summary ("" when it must not be asked).
report::RunReportInput report_input(const RunEnd& end, bool success, const std::string& verdict,
                                    const std::string& environment) {
  report::RunReportInput input;
  report::RunHeader& h = input.header;
  h.app = end.app.name;
  h.proof = end.proof;
  h.description = end.app.description;
  h.scenario = end.runtime.scenario();
  h.seed = end.options.seed;
  h.realtime = end.options.realtime;
  h.requested = end.options.duration;
  h.end = seconds_of(end.runtime.now());
  h.stop_reason = end.runtime.stop_reason();
  h.success = success;
  h.verdict = verdict;
  h.environment = environment;
  for (const ConnectionStats& s : end.runtime.stats()) {  // the connections mediated here
    const model::Connection& c = end.app.connections[s.model_index];
    input.connections.push_back(
        {s, c.kind == model::ConnectionKind::Feed, c.constraint.to_string()});
  }
  input.transport = {end.placement, end.runtime.transport_status()};
  input.records = &end.records;
  if (end.claims) {
    input.checks_watched = true;
    for (const std::string& claim : end.claims->watched())
      input.checks.push_back({claim, false, 0, {}});
    for (const ClaimViolation& v : end.claims->violations()) {
      std::string claim = broken_claim_name(v);
      auto row = std::find_if(input.checks.begin(), input.checks.end(),
                              [&](const report::CheckRow& c) { return c.claim == claim; });
      if (row == input.checks.end())
        row = input.checks.insert(input.checks.end(), {claim, false, 0, {}});
      row->broken = true, row->at = seconds_of(v.t), row->what = v.what;
    }
  }
  return input;
}

void print_run_line(const RunEnd& end, const std::string& stop_reason) {
  double run =
      seconds_of(end.runtime.now());  // in the unit of the run's length, as the report writes it
  std::printf(
      "app %s, scenario %s, seed %llu, %s time %s%s%s\n", end.app.name.c_str(),
      end.runtime.scenario().c_str(), static_cast<unsigned long long>(end.options.seed),
      end.options.realtime ? (end.options.time_scale != 1 ? "scaled real" : "real") : "simulated",
      TimeFormat::for_run(run).text(run).c_str(),
      stop_reason.empty() ? "" : ", stopped: ", stop_reason.c_str());
  if (!end.placement.empty()) std::printf("transport: %s\n", end.placement.c_str());
  std::fputs(end.runtime.stats_table().c_str(), stdout);
  std::fputs(end.runtime.transport_summary().c_str(), stdout);
}

// Writes the report, if one was asked for; false (after saying why) when it cannot be written.
bool write_report(const RunEnd& end, const report::RunReportInput& input) {
  if (end.report_path.empty()) return true;
  std::string html = report::render_run_report(input);
  std::string error;
  if (!end.report_file.write(html, &error)) {
    std::fprintf(stderr, "arbc run: error: %s\n", error.c_str());
    return false;
  }
  std::printf("report: %s (%zu bytes)\n", end.report_path.c_str(), html.size());
  return true;
}

// Messages the proof excluded and the runtime dropped before delivery (bad-value: a list longer
// than the proof of its rule covers): the run stayed inside the proof, so no failure, but said.
void excluded_values(const RunEnd& end) {
  uint64_t n = 0;
  for (const ConnectionStats& s : end.runtime.stats()) n += s.drops(DropReason::BadValue);
  if (n == 0) return;
  std::printf(
      "runtime checks: %llu %s the proof excluded dropped (bad-value: lists longer than it "
      "covers; see the trace)\n",
      static_cast<unsigned long long>(n), n == 1 ? "message" : "messages");
}

// The runtime checks' lines; with --runtime-checks fail a violation makes the run a failure,
// named in the verdict (what the proof no longer covers, and from when).
void judge_claims(const RunEnd& end, RunVerdict* verdict) {
  if (!end.claims) return;
  end.claims->finish(end.runtime.now());
  const std::vector<ClaimViolation>& broken = end.claims->violations();
  auto unwatched = [&] {  // what the spec assumes and no run can see: not counted kept
    for (const std::string& u : end.claims->unwatched())
      std::printf("runtime checks: not watched: %s\n", u.c_str());
  };
  if (broken.empty()) {
    size_t n = end.claims->size();
    std::printf("runtime checks: %zu %s of the proof watched, none broken\n", n,
                n == 1 ? "claim or assumption" : "claims and assumptions");
    unwatched();
    return;
  }
  std::printf("runtime checks: %zu of %zu broken; the proof does not cover the run from %s%s:\n",
              broken.size(), end.claims->size(), duration_literal(broken.front().t).c_str(),
              end.claims_fail ? "" : " (--runtime-checks fail makes this a failure)");
  for (const ClaimViolation& v : broken)
    std::printf("  %s  %s: %s\n", duration_literal(v.t).c_str(), broken_claim_name(v).c_str(),
                v.what.c_str());
  unwatched();
  *verdict = with_broken_claims(*verdict, broken, end.claims_fail);
}

}  // namespace

int finish_run(const RunEnd& end, const std::string& signal) {
  if (!signal.empty()) std::fprintf(stderr, "arbc run: interrupted (%s)\n", signal.c_str());
  // The run line and the report name the signal: Ctrl-C and a service manager's SIGTERM are
  // different stories when the report is read later.
  std::string stop = end.runtime.stop_reason();
  if (!signal.empty() && stop == "interrupted") stop += " by " + signal;
  print_run_line(end, stop);
  RunVerdict verdict;
  std::string summary;
  if (Environment* env = end.runtime.environment()) {
    summary = env->summary();
    if (!summary.empty()) {
      std::fputs(summary.c_str(), stdout);
      if (summary.back() != '\n') std::fputc('\n', stdout);
    }
    verdict = judge_by_environment(env->success());
  } else {
    verdict = judge_without_environment(end.runtime.stats(), end.runtime.input_stats());
  }
  if (end.stand_ins) {
    std::string received = end.stand_ins();
    std::fputs(received.c_str(), stdout);
    summary += (summary.empty() || summary.back() == '\n' ? "" : "\n") + received;
  }
  excluded_values(end);
  judge_claims(end, &verdict);
  std::printf("result: %s\n", verdict.text.c_str());
  report::RunReportInput input = report_input(end, verdict.success, verdict.text, summary);
  input.header.stop_reason = stop;
  if (!write_report(end, input)) return 3;
  return verdict.success ? 0 : 3;
}

void give_up_stuck_run(const RunEnd& end, const std::string& signal, double waited) {
  BusyMarker::Snapshot busy = end.runtime.busy();
  std::string who = Runtime::describe(busy);
  // The budget as a spec writes durations (500ms); the measured waits, to a tenth of a second,
  // in the same form, so that the sentence does not mix `0.6 s` and `500ms`.
  std::string waited_text = duration_literal(std::round(waited * 10) / 10);
  std::string why;
  if (who.empty()) {
    why = "the run did not stop within " + waited_text;
  } else {
    std::string budget =
        busy.kind == "monitor"
            ? ", past its wall-clock budget of " + duration_literal(end.options.limits.wall_seconds)
        : busy.kind == "transport" ? " (closing its endpoints)"
                                   : " (plugin code cannot be stopped)";
    why = who + " is still running " + waited_text + " after the interrupt" + budget;
  }
  std::fprintf(stderr, "arbc run: interrupted (%s), but %s; ending the run without it\n",
               signal.c_str(), why.c_str());
  std::string stop = "interrupted; " + why;
  end.runtime.abandon_trace(stop);
  print_run_line(end, stop);
  std::string verdict = "interrupted (the run did not finish)";
  std::printf("result: %s\n", verdict.c_str());
  report::RunReportInput input = report_input(end, false, verdict, "");
  input.header.stop_reason = stop;
  write_report(end, input);
}

}  // namespace arbc::cli
