#include "cli/yarp_verify.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <set>

#include "import/yarp/yarp_import.h"

namespace arbc::cli {
namespace {

verify::Finding to_finding(const Diagnostic& d) {
  verify::Finding f;
  f.check = d.id;
  f.severity = d.severity;
  f.message = d.message;
  f.loc = d.loc;
  for (const Diagnostic& n : d.notes) f.notes.push_back({n.message, n.loc});
  return f;
}

bool set_anywhere(const model::App& app, const std::string& event) {
  return std::any_of(app.connections.begin(), app.connections.end(), [&](const auto& c) {
    return std::count(c.sets.begin(), c.sets.end(), event) > 0;
  });
}

bool read_anywhere(const model::App& app, const std::string& event) {
  return std::any_of(app.connections.begin(), app.connections.end(), [&](const auto& c) {
    std::set<std::string> read;
    c.constraint.collect_events(read);
    return c.kind == model::ConnectionKind::Rule && read.count(event) > 0;
  });
}

// `unfed` means "no connection into this port sets it" and `unused` "no rule of this port reads
// it"; in YARP an event set by a monitor into another port of the same process is visible, and
// yarp-shared-event says so instead.
void drop_cross_port_findings(const model::App& app, verify::VerifyReport& report) {
  auto cross_port = [&](const verify::Finding& f) {
    return (f.check == verify::kCheckUnfed && set_anywhere(app, f.event)) ||
           (f.check == verify::kCheckUnused && read_anywhere(app, f.event));
  };
  for (verify::PortResult& p : report.ports) std::erase_if(p.findings, cross_port);
  std::erase_if(report.app_findings, cross_port);
}

// A note at the Lua line that sets each involved rule's constraint.
void point_at_scripts(const yarp::YarpImport& im, verify::VerifyReport& report) {
  for (verify::PortResult& p : report.ports) {
    for (verify::Finding& f : p.findings) {
      if (f.check != verify::kCheckExclusive && f.check != verify::kCheckAssert) continue;
      for (const std::string& rule : f.rules) {
        for (size_t i = 0; i < im.app.connections.size(); ++i) {
          const model::Connection& c = im.app.connections[i];
          const yarp::ImportedConnection& ic = im.connections[i];
          if (c.destination != p.port || c.name != rule || !ic.analysed || !ic.monitor ||
              !ic.monitor->has_constraint)
            continue;
          f.notes.push_back({"'" + rule + "' sets its constraint `" + ic.meaning.text + "` here",
                             ic.monitor->constraint_loc});
        }
      }
    }
  }
}

bool has_error(const std::vector<verify::Finding>& findings) {
  return std::any_of(findings.begin(), findings.end(), [](const verify::Finding& f) {
    return f.severity == Severity::Error && f.check != verify::kCheckUnknown;
  });
}

void recompute_verdicts(verify::VerifyReport& report) {
  bool refuted = has_error(report.app_findings), unknown = false;
  for (verify::PortResult& p : report.ports) {
    p.verdict = has_error(p.findings)       ? verify::Verdict::Refuted
                : !p.unknown_reason.empty() ? verify::Verdict::Unknown
                                            : verify::Verdict::Proved;
    refuted |= p.verdict == verify::Verdict::Refuted;
    unknown |= p.verdict == verify::Verdict::Unknown;
  }
  report.verdict = refuted   ? verify::Verdict::Refuted
                   : unknown ? verify::Verdict::Unknown
                             : verify::Verdict::Proved;
}

// The importer's findings (a monitor that does not load, a constraint YARP evaluates
// otherwise, ...) are what the proof started from, so each goes before the verifier's findings
// it causes (an overlap of a rule taken as always selected), in the import's order.
void put_causes_first(const yarp::YarpImport& im, verify::VerifyReport& report) {
  std::map<std::string, std::vector<verify::Finding>> by_port;
  std::vector<verify::Finding> app;
  for (size_t i = 0; i < im.diagnostics.size(); ++i) {
    verify::Finding f = to_finding(im.diagnostics[i]);
    f.port = im.diagnostic_ports[i];
    bool known = std::any_of(report.ports.begin(), report.ports.end(),
                             [&](const verify::PortResult& p) { return p.port == f.port; });
    if (known) {
      by_port[f.port].push_back(std::move(f));
    } else {
      f.port.clear();
      app.push_back(std::move(f));
    }
  }
  for (verify::PortResult& p : report.ports) {
    std::vector<verify::Finding>& causes = by_port[p.port];
    p.findings.insert(p.findings.begin(), std::make_move_iterator(causes.begin()),
                      std::make_move_iterator(causes.end()));
  }
  report.app_findings.insert(report.app_findings.begin(), std::make_move_iterator(app.begin()),
                             std::make_move_iterator(app.end()));
}

}  // namespace

bool is_yarp_application(const std::string& input) {
  return input.size() > 4 && input.compare(input.size() - 4, 4, ".xml") == 0;
}

YarpVerify verify_yarp_application(const std::string& xml, const verify::VerifyOptions& options,
                                   const std::vector<std::string>& search_paths) {
  YarpVerify out;
  yarp::YarpImport im = yarp::import_yarp(xml, {search_paths});
  if (!im.ok) {
    SourceCache sources;
    for (const Diagnostic& d : im.diagnostics) out.diagnostics += render(d, &sources);
    out.diagnostics += "arbc verify: " + xml + ": not verified (fix the errors above)\n";
    return out;
  }
  std::string error;
  std::optional<verify::VerifyReport> report = verify::verify_app(im.app, options, &error);
  if (!report) {
    out.diagnostics = "arbc verify: " + xml + ": " + error + "\n";
    return out;
  }
  out.report = std::move(*report);
  drop_cross_port_findings(im.app, out.report);
  point_at_scripts(im, out.report);
  put_causes_first(im, out.report);
  recompute_verdicts(out.report);
  out.ok = true;
  return out;
}

}  // namespace arbc::cli
