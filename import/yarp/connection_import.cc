// One <connection> of the XML: its carrier, its monitor found and analysed, its constraint as
// YARP evaluates it. Part of yarp_import.h.
#include "import/yarp/connection_import.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "import/yarp/app_xml.h"
#include "import/yarp/script_locator.h"
#include "import/yarp/yarp_require.h"

namespace arbc::yarp {
namespace {

Diagnostic diag(Severity s, const model::SourceLocation& loc, std::string message, const char* id) {
  Diagnostic d;
  d.severity = s;
  d.loc = loc;
  d.message = std::move(message);
  d.id = id;
  return d;
}

Diagnostic note(std::string message, model::SourceLocation loc = {}) {
  return diag(Severity::Note, loc, std::move(message), "");
}

// The monitor could not be run: say why, and that the proof takes it as always selected.
void script_error(const ImportedConnection& ic, const MonitorAnalysis& m,
                  std::vector<Diagnostic>& out) {
  std::string what = !m.run.loaded ? "the script does not load: " : "PortMonitor.create fails: ";
  Diagnostic d = diag(Severity::Error, ic.xml.protocol_loc,
                      "the monitor " + m.path + " of " + ic.xml.from + " -> " + ic.xml.to +
                          " cannot be analysed; " + what + m.run.error,
                      kIdScriptError);
  bool stand_in = m.run.error.find("arbc's stand-in") != std::string::npos;
  d.notes.push_back(note(
      stand_in ? "it calls part of YARP's Lua bindings that arbc's stand-in does not offer; if "
                 "it runs on YARP, the proof still holds: arbc takes the connection as always "
                 "selected and setting any event"
               : "on YARP this connection fails to load or rejects every message (a Lua error "
                 "in create, or create not returning true); arbc takes it as always selected "
                 "and setting any event"));
  // Lua names the script's line ("ball.lua:3: ')' expected near 'return'"): point there too,
  // so the user lands on the line to fix, not only on the XML's <protocol>.
  std::string prefix = m.path + ":";
  if (m.run.error.compare(0, prefix.size(), prefix) == 0) {
    int line = std::atoi(m.run.error.c_str() + prefix.size());
    if (line > 0) {
      d.notes.push_back(note(!m.run.loaded
                                 ? "Lua reports the error here; YARP cannot load the script either"
                                 : "create fails here",
                             locate(m.path, m.text, line, "")));
    }
  }
  out.push_back(std::move(d));
}

// A setConstraint outside create and the top level: the constraint changes while it runs.
const MonitorCall* constraint_set_later(const ScriptFacts& f) {
  for (const MonitorCall& c : f.calls) {
    if (c.function == "setConstraint" && !c.callback.empty() && c.callback != "create") return &c;
  }
  return nullptr;
}

bool read_text(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return true;
}

}  // namespace

ImportedConnection import_connection(const XmlConnection& xml, const std::string& xml_file,
                                     const YarpImportOptions& options, YarpEvaluator& evaluator,
                                     std::vector<Diagnostic>& out, bool& bad_input) {
  ImportedConnection ic;
  ic.xml = xml;
  ic.meaning = constraint_meaning(evaluator, "");
  std::string err;
  if (!parse_carrier(xml.protocol, &ic.carrier, &err)) {
    out.push_back(diag(Severity::Error, xml.protocol_loc, err, kIdCarrier));
    return ic;  // not analysed: always selected
  }
  if (ic.carrier.send_monitor) {
    Diagnostic d = diag(Severity::Warning, xml.protocol_loc,
                        "`send.portmonitor` runs the monitor in the sending process: YARP "
                        "never evaluates its constraint there, and its events are not in the "
                        "receiving process",
                        kIdCarrier);
    d.notes.push_back(
        note("arbitrate with `recv.portmonitor` (the monitor runs beside the "
             "destination port)"));
    out.push_back(std::move(d));
    ic.analysed = true;  // a plain connection as far as arbitration goes
    return ic;
  }
  if (!ic.carrier.monitor) {
    ic.analysed = true;
    return ic;
  }
  if (ic.carrier.type != "lua") {
    out.push_back(diag(Severity::Warning, xml.protocol_loc,
                       "a `type." + ic.carrier.type +
                           "` monitor is compiled code arbc cannot read: taken as always "
                           "selected and setting any event",
                       kIdCarrier));
    return ic;
  }
  ScriptLookup lookup =
      locate_script(ic.carrier.file, ic.carrier.context, xml_file, options.search_paths);
  std::string text;
  if (!lookup.found || !read_text(*lookup.found, text)) {
    Diagnostic d = diag(
        Severity::Error, xml.protocol_loc,
        "the monitor '" + ic.carrier.file + "' of " + xml.from + " -> " + xml.to + " is not found",
        kIdMonitorMissing);
    std::string tried;
    for (const std::string& t : lookup.tried) tried += (tried.empty() ? "" : ", ") + t;
    d.notes.push_back(note("tried " + tried));
    d.notes.push_back(note("give the folder that holds it with --yarp-path DIR"));
    out.push_back(std::move(d));
    bad_input = true;
    return ic;
  }
  MonitorContext context{*lookup.found, xml.from, xml.to, ic.carrier.base};
  ic.monitor = analyse_monitor(*lookup.found, text, context, ic.carrier, xml.protocol_loc);
  const MonitorAnalysis& m = *ic.monitor;
  if (!m.run.loaded || !m.run.created) {
    script_error(ic, m, out);
    return ic;
  }
  check_requires_yarp(ic, out);
  if (const MonitorCall* late = constraint_set_later(m.facts)) {
    Diagnostic d = diag(Severity::Warning, locate(m.path, m.text, late->line, "setConstraint"),
                        "the monitor " + m.path + " of " + xml.from + " -> " + xml.to +
                            " changes its constraint after create: arbc takes the connection "
                            "as always selected",
                        kIdOpaque);
    d.notes.push_back(note("set the constraint once, in create, and select with events"));
    out.push_back(std::move(d));
    return ic;  // not analysed: always selected, opaque
  }
  ic.meaning = constraint_meaning(evaluator, m.constraint);
  ic.analysed = true;
  return ic;
}

}  // namespace arbc::yarp
