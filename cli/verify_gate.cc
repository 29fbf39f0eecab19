#include "cli/verify_gate.h"

#include <cstdio>
#include <cstdlib>

#include "cli/build_summary.h"
#include "cli/commands.h"
#include "harness/monitor_runner.h"
#include "harness/test_replayer.h"
#include "verify/report_format.h"
#include "verify/verify.h"

namespace arbc::cli {

std::string verified_summary(size_t exclusive, size_t by_priority) {
  if (exclusive + by_priority == 0) return "verified: no arbitrated ports, nothing to prove";
  std::string line = "verified: ";
  if (exclusive > 0)
    line += count_of(exclusive, "arbitrated port", "arbitrated ports") + " proved exclusive";
  if (by_priority == 0) return line;
  if (exclusive > 0) line += "; ";
  // The wording of verify's own line for such a port (verify/report_text.cc).
  return line + count_of(by_priority, "arbitrated port", "arbitrated ports") +
         " by priority: a rule's delivery holds every rule below it off for its hold";
}

std::string verified_summary(const std::vector<model::ArbitratedPort>& ports) {
  size_t by_priority = 0;
  for (const model::ArbitratedPort& p : ports) by_priority += p.by_priority ? 1 : 0;
  return verified_summary(ports.size() - by_priority, by_priority);
}

VerifyGate verify_before_writing(const model::App& app, const std::string& input,
                                 SourceCache* sources, bool strict, const std::string& refusal,
                                 const char* command) {
  VerifyGate gate;
  verify::VerifyOptions options;
  options.strict = strict;
  harness::LuaMonitorRunner runner(input,
                                   app);  // message counterexamples are replayed, as in verify
  options.runner = &runner;
  harness::RuntimeTestReplayer replayer(input);  // and counterexamples over time
  options.test_replayer = &replayer;
  options.on_stuck = [&app, &input, &refusal, command, &options] {
    verify::VerifyReport stuck = verify::stuck_report(app, options.timeout_seconds);
    std::fprintf(stderr, "%s: %s\n%s: verification unknown; %s\n", input.c_str(),
                 stuck.app_findings[0].message.c_str(), command, refusal.c_str());
    std::_Exit(kExitRefuted);  // the main thread is inside Z3 and cannot be ended otherwise
  };
  std::string error;
  std::optional<verify::VerifyReport> verified = verify::verify_app(app, options, &error);
  if (!verified) {
    std::fprintf(stderr, "%s: error: cannot verify: %s\n", input.c_str(), error.c_str());
    gate.exit_code = kExitBadInput;
    return gate;
  }
  const verify::VerifyReport& report = *verified;
  bool findings = report.count(Severity::Error) + report.count(Severity::Warning) > 0;
  if (report.verdict != verify::Verdict::Proved || findings) {
    std::string text = verify::format_text({{input, report}}, sources, /*stats=*/false);
    std::fputs(text.c_str(), stderr);
  }
  if (report.verdict != verify::Verdict::Proved) {
    std::fprintf(stderr, "%s: verification %s; %s\n", command, verify::verdict_name(report.verdict),
                 refusal.c_str());
    gate.exit_code = kExitRefuted;
    return gate;
  }
  gate.pass = true;
  gate.summary = verified_summary(app.arbitrated_ports);
  gate.bounded_rules = report.bounded_rules;
  gate.list_bound = report.list_bound;
  return gate;
}

void apply_list_bounds(const VerifyGate& gate, model::App& app) {
  for (model::Connection& c : app.connections)
    for (const auto& [destination, name] : gate.bounded_rules)
      if (c.destination == destination && c.name == name) c.list_bound = gate.list_bound;
}

}  // namespace arbc::cli
