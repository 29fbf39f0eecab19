#include "import/yarp/yarp_verify.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <optional>
#include <set>

#include "import/yarp/app_xml.h"
#include "import/yarp/yarp_import.h"

namespace arbc::yarp {
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

// Where the monitor defines PortMonitor.create (where a constraint is set), else `fallback`.
model::SourceLocation create_call(const yarp::MonitorAnalysis& m,
                                  const model::SourceLocation& fallback) {
  size_t at = m.text.find("PortMonitor.create");
  if (at == std::string::npos) return fallback;
  int line = 1 + static_cast<int>(std::count(m.text.begin(), m.text.begin() + at, '\n'));
  return yarp::locate(m.path, m.text, line, "PortMonitor.create");
}

// A note at the Lua line that sets each involved rule's constraint, or where it would.
void point_at_scripts(const yarp::YarpImport& im, verify::VerifyReport& report) {
  for (verify::PortResult& p : report.ports) {
    for (verify::Finding& f : p.findings) {
      if (f.check != verify::kCheckExclusive && f.check != verify::kCheckAssert &&
          f.check != verify::kCheckUnfed)
        continue;
      for (const std::string& rule : f.rules) {
        for (size_t i = 0; i < im.app.connections.size(); ++i) {
          const model::Connection& c = im.app.connections[i];
          const yarp::ImportedConnection& ic = im.connections[i];
          if (c.destination != p.port || c.name != rule || !ic.analysed || !ic.monitor) continue;
          if (ic.monitor->has_constraint) {
            f.notes.push_back({"'" + rule + "' sets its constraint `" + ic.meaning.text + "` here",
                               ic.monitor->constraint_loc});
          } else if (f.check == verify::kCheckExclusive) {
            f.notes.push_back({"'" + rule +
                                   "' sets no constraint (no PortMonitor.setConstraint in its " +
                                   "create), so YARP selects it whatever the events: set one here",
                               create_call(*ic.monitor, ic.xml.protocol_loc)});
          }
        }
      }
    }
  }
}

// An event no monitor sets is most often a misspelt constraint, which the proof then takes as
// free: the overlap it reports follows from the misspelling, so the misspelling goes first.
void unfed_first(verify::VerifyReport& report) {
  for (verify::PortResult& p : report.ports) {
    std::stable_partition(p.findings.begin(), p.findings.end(),
                          [](const verify::Finding& f) { return f.check == verify::kCheckUnfed; });
  }
}

bool same_place(const model::SourceLocation& a, const model::SourceLocation& b) {
  return a.file == b.file && a.line == b.line && a.column == b.column;
}

// The setEvent call of `event` in connection i's monitor, if the monitor was read and has one.
std::optional<model::SourceLocation> set_event_call(const yarp::YarpImport& im, size_t i,
                                                    const std::string& event) {
  const yarp::ImportedConnection& ic = im.connections[i];
  if (!ic.monitor) return std::nullopt;
  for (const yarp::MonitorCall& c : ic.monitor->facts.calls) {
    if (c.function == "setEvent" && c.text == event)
      return yarp::locate(ic.monitor->path, ic.monitor->text, c.line, "setEvent");
  }
  return std::nullopt;
}

// The verifier's advice speaks the spec: an `exclusive` group or `invariant` to declare,
// `events from M.p { e }` or `set e` in a monitor, a "did you mean" at the connection that sets
// the close name. A YARP application has no such declarations, sets events with
// PortMonitor.setEvent, and the user fixes the Lua line, so the notes say that and point there.
void advice_in_yarp_words(const yarp::YarpImport& im, verify::VerifyReport& report) {
  for (verify::PortResult& p : report.ports) {
    for (verify::Finding& f : p.findings) {
      if (f.check == verify::kCheckExclusive) {
        for (verify::Note& n : f.notes) {
          if (n.message.rfind("make the constraints exclusive", 0) != 0) continue;
          n.message =
              "make the constraints exclusive (`not EVENT` in one monitor's "
              "PortMonitor.setConstraint), or have the monitors that set the events never leave "
              "this state (unset one event as they set the other)";
        }
      }
      if (f.check != verify::kCheckUnfed) continue;
      for (verify::Note& n : f.notes) {
        if (n.message.rfind("feed it into the port", 0) == 0) {
          n.message = "set it with PortMonitor.setEvent(\"" + f.event +
                      "\") in the monitor of a connection into " + p.port +
                      ", or correct the name where the constraint reads it";
        } else if (n.message.rfind("did you mean '", 0) == 0) {
          size_t from = n.message.find('\'') + 1;
          std::string meant = n.message.substr(from, n.message.find('\'', from) - from);
          for (size_t i = 0; i < im.app.connections.size(); ++i) {
            const model::Connection& c = im.app.connections[i];
            if (c.destination != p.port || !same_place(c.loc, n.loc)) continue;
            if (std::optional<model::SourceLocation> at = set_event_call(im, i, meant)) n.loc = *at;
          }
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
  advice_in_yarp_words(im, out.report);
  unfed_first(out.report);
  put_causes_first(im, out.report);
  recompute_verdicts(out.report);
  out.ok = true;
  return out;
}

}  // namespace arbc::yarp
