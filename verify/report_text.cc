#include "verify/temporal/report_text.h"

#include <cstdio>

#include "core/join.h"
#include "verify/report_format.h"

namespace arbc::verify {
namespace {

// At most kListed names, then "..., last (N in all)": a 1,000-rule port stays one readable
// line. The JSON and SARIF reports keep every name.
constexpr size_t kListed = 12;

std::string listed(const std::vector<std::string>& items) {
  if (items.empty()) return "none";
  if (items.size() <= kListed) return join(items);
  std::vector<std::string> first(items.begin(), items.begin() + (kListed - 2));
  return join(first) + ", ..., " + items.back() + " (" + std::to_string(items.size()) + " in all)";
}

std::string plural(size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", s);
  return buf;
}

// "PickAndPlace.cmd: proved: ..." or "...: refuted (2 errors, 1 warning)".
std::string port_line(const PortResult& p, bool stats) {
  std::string line = "  " + p.port;
  if (p.by_priority && p.complete) {
    line += " (by priority, complete)";
  } else if (p.by_priority) {
    line += " (by priority)";
  } else if (p.complete) {
    line += " (complete)";
  }
  line += ": ";
  line += verdict_name(p.verdict);
  if (p.verdict == Verdict::Proved && p.list_bound)
    line += " for lists of at most " + std::to_string(p.list_bound) + " elements";
  if (p.verdict == Verdict::Proved) {
    if (p.rules.empty()) {
      line += ": no rule delivers, nothing can overlap";
    } else if (p.rules.size() == 1) {
      line += ": one rule (" + p.rules[0] + "), nothing can overlap";
    } else if (p.by_priority) {
      // The proof counts a rule's hold as part of its delivery: a lower rule can still deliver
      // in a state just before a higher one does (docs/design.md#priorities-and-holds).
      line += ": a rule's delivery holds every rule below it off for its hold (" + listed(p.rules) +
              ", highest first); in one event state a higher rule may still deliver right after "
              "a lower one";
    } else {
      line += ": rules " + listed(p.rules) + " are never selected together";
    }
    if (p.complete) line += "; some rule is selected in every state";
    if (p.asserts) {
      line += "; " + plural(static_cast<size_t>(p.asserts), "assert") +
              (p.asserts == 1 ? " holds" : " hold");
    }
  } else {
    if (p.verdict == Verdict::Unknown) line += " (" + p.unknown_reason + ")";
    size_t errors = 0, warnings = 0;
    for (const Finding& f : p.findings) {
      errors += f.severity == Severity::Error;
      warnings += f.severity == Severity::Warning;
    }
    line += ": " + plural(errors, "error") + ", " + plural(warnings, "warning");
  }
  if (p.overlapping_pairs) {
    line += "; " + plural(static_cast<size_t>(p.overlapping_pairs), "overlapping pair") + " (" +
            std::to_string(p.reported_pairs) + " shown)";
  }
  if (stats) {
    line += " [" + seconds_text(p.seconds) + ", " + std::to_string(p.solver_queries) +
            " solver quer" + (p.solver_queries == 1 ? "y" : "ies") + "]";
  }
  line += "\n    over " + plural(p.events.size(), "event") + " (" + listed(p.events) +
          "); invariants used: " + listed(p.invariants);
  if (p.exclusive_groups) line += "; exclusive groups used: " + std::to_string(p.exclusive_groups);
  if (!p.feeds.empty()) line += "\n    event feeds (never deliver): " + listed(p.feeds);
  line += "\n";
  for (const std::string& d : p.exclusive_by_data) line += "    exclusive by data: " + d + "\n";
  for (const std::string& d : p.exclusive_by_delivery)
    line += "    exclusive by delivery: " + d + "\n";
  return line;
}

// "resource arm (PickAndPlace.cmd, PullObject.cmd): proved: ..." and why, per pair.
std::string resource_lines(const ResourceResult& r) {
  std::string line =
      "  resource " + r.name + " (" + join(r.ports) + "): " + verdict_name(r.verdict);
  if (r.verdict == Verdict::Proved && r.list_bound)
    line += " for lists of at most " + std::to_string(r.list_bound) + " elements";
  if (r.verdict == Verdict::Proved) {
    line += r.pairs == 0 ? ": no two rules into different ports"
                         : ": " + plural(static_cast<size_t>(r.pairs), "pair") +
                               " of rules never both use it";
  } else {
    if (r.verdict == Verdict::Unknown) line += " (" + r.unknown_reason + ")";
    size_t errors = 0;
    for (const Finding& f : r.findings) errors += f.severity == Severity::Error;
    line += ": " + plural(errors, "error");
  }
  line += "\n";
  for (const std::string& p : r.exclusive_by_events) line += "    exclusive by events: " + p + "\n";
  for (const std::string& p : r.exclusive_by_data) line += "    exclusive by data: " + p + "\n";
  return line;
}

// "[dead] rule 'pull' of PullObject.cmd": what a warning that --strict made an error is about.
std::string strict_item(const Finding& f) {
  std::string what = "[" + f.check + "] ";
  if (!f.event.empty())
    return what + "event '" + f.event + "'" + (f.port.empty() ? "" : " of " + f.port);
  if (!f.rules.empty())
    return what + "rule '" + f.rules[0] + "'" + (f.port.empty() ? "" : " of " + f.port);
  return what + f.port;
}

// The warnings that failed the run only because of --strict, for the summary line.
std::vector<std::string> strict_failures(const std::vector<InputReport>& inputs) {
  std::vector<std::string> out;
  auto add = [&](const Finding& f) {
    if (f.strict && f.severity == Severity::Error) out.push_back(strict_item(f));
  };
  for (const InputReport& in : inputs) {
    for (const PortResult& p : in.report.ports)
      for (const Finding& f : p.findings) add(f);
    for (const Finding& f : in.report.app_findings) add(f);
  }
  return out;
}

}  // namespace

std::string format_text(const std::vector<InputReport>& inputs, SourceCache* sources, bool stats) {
  std::string out;
  size_t ports = 0, rules = 0, errors = 0, warnings = 0, properties = 0;
  size_t by_outcome[temporal::kOutcomes] = {};  // TemporalResult::Outcome
  bool refuted = false, unknown = false;
  size_t bad = 0;
  double seconds = 0;
  for (const InputReport& in : inputs) {
    if (in.bad_input()) {
      ++bad;
      continue;
    }
    const VerifyReport& r = in.report;
    out += r.app.empty() ? in.input + ":\n" : r.app + " (" + in.input + "):\n";
    if (r.ports.empty()) out += "  no arbitrated ports\n";
    for (const PortResult& p : r.ports) {
      out += port_line(p, stats);
      for (const Finding& f : p.findings) out += render(to_diagnostic(f), sources);
      ++ports;
      rules += p.rules.size();
    }
    for (const Finding& f : r.app_findings) out += render(to_diagnostic(f), sources);
    for (const ResourceResult& res : r.resources) {
      out += resource_lines(res);
      for (const Finding& f : res.findings) out += render(to_diagnostic(f), sources);
    }
    if (!r.assumptions.empty())
      out += "  message data assumed: " + join(r.assumptions, "; ") + "\n";
    for (const TemporalResult& t : r.temporal) {
      out += temporal::temporal_text(t);
      properties += 1;
      by_outcome[static_cast<int>(t.outcome)] += 1;
    }
    errors += static_cast<size_t>(r.count(Severity::Error));
    warnings += static_cast<size_t>(r.count(Severity::Warning)) + in.warnings.size();
    refuted |= r.verdict == Verdict::Refuted;
    unknown |= r.verdict == Verdict::Unknown;
    seconds += r.seconds;
  }
  const char* verdict = bad ? "error" : refuted ? "refuted" : unknown ? "unknown" : "proved";
  out += std::string(verdict) + ": " + plural(ports, "port") + ", " + plural(rules, "rule") + "; " +
         plural(errors, "error") + ", " + plural(warnings, "warning");
  if (properties) {
    out += "; " + std::to_string(properties) + (properties == 1 ? " property" : " properties") +
           " over time: " + temporal::outcome_counts(by_outcome);
  }
  if (bad) out += "; " + plural(bad, "input") + " not verified (bad input, on stderr)";
  std::vector<std::string> strict = strict_failures(inputs);
  if (!strict.empty()) out += "; warnings made errors by --strict: " + join(strict);
  if (stats) out += "; " + seconds_text(seconds);
  return out + "\n";
}

}  // namespace arbc::verify
