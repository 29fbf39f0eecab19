#include "import/yarp/spec_writer.h"

#include <filesystem>
#include <map>
#include <set>

#include "core/effective_guard.h"
#include "import/yarp/spec_names.h"

namespace arbc::yarp {
namespace {

std::string qualified(const std::map<std::string, SpecPort>& ports, const std::string& yarp) {
  const SpecPort& p = ports.at(yarp);
  return p.module + "." + p.port;
}

std::string duration(Nanos d) { return decimal_seconds(d) + "s"; }

std::string modules_text(const std::map<std::string, SpecPort>& ports) {
  std::map<std::string, std::vector<std::string>> by_module;
  for (const auto& [yarp, p] : ports) {
    by_module[p.module].push_back(std::string(p.out ? "out " : "in ") + p.port + ": Bottle;");
  }
  std::string s;
  for (const auto& [module, decls] : by_module) {
    s += "module " + module + " {";
    for (const std::string& d : decls) s += " " + d;
    s += " }\n";
  }
  return s;
}

std::string events_text(const YarpImport& im) {
  std::string s;
  for (const model::Event& e : im.app.events) {
    if (identifier(e.name) != e.name) {
      s += "// event '" + e.name + "' has no spec name; constraints that read it are commented\n";
      continue;
    }
    s += "event " + e.name + (e.lifetime ? " lifetime " + duration(*e.lifetime) : "") + ";\n";
  }
  for (const model::ExclusiveGroup& g : im.app.exclusive_groups) {
    s += "exclusive { " + g.events[0] + ", " + g.events[1] + " };  // " +
         std::filesystem::path(g.loc.file.str()).filename().string() +
         " sets one only with the other unset\n";
  }
  return s;
}

// A spec string literal of `text` (docs/language.md: `\"` and `\\` escapes), so a quote in
// the XML's <description> is kept rather than lost. With `collapse`, runs of white space (the
// line breaks of an indented multi-line <description>) become one space.
std::string spec_string(const std::string& text, bool collapse) {
  std::string out = "\"";
  bool blank = false;
  for (char c : text) {
    if (collapse && (c == ' ' || c == '\n' || c == '\t' || c == '\r')) {
      blank = true;
      continue;
    }
    if (blank) out += ' ';
    blank = false;
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// `script "path";` relative to the spec's folder, as the compiler reads it, so the spec and
// the monitors can be moved together. Both paths are made absolute first: the monitor's is
// relative to the working directory, or absolute (an absolute XML path, a YARP data folder),
// and lexically_relative between an absolute and a relative path has no answer. Symbolic
// links are kept as named (a monitor linked into the XML's folder stays there).
std::string script_body(const ImportedConnection& ic, const std::string& spec_path) {
  if (!ic.monitor) return ";";
  namespace fs = std::filesystem;
  std::error_code ec_monitor, ec_base;  // no working directory: the path as found
  fs::path monitor = fs::absolute(ic.monitor->path, ec_monitor).lexically_normal();
  fs::path base = fs::absolute(spec_path, ec_base).lexically_normal().parent_path();
  fs::path rel = ec_monitor || ec_base ? fs::path() : monitor.lexically_relative(base);
  std::string p = rel.empty() ? ic.monitor->path : rel.generic_string();
  return " { script " + spec_string(p, false) + "; }";
}

bool spec_names_ok(const Constraint& c) {
  std::set<std::string> events;
  c.collect_events(events);
  for (const std::string& e : events) {
    if (identifier(e) != e) return false;
  }
  return true;
}

// What arbc could not follow in the connection's monitor, said where the reader of the spec
// sees it (the import's warnings on stderr are gone once the spec is written).
std::string unknowns_text(const ImportedConnection& ic) {
  if (!ic.monitor) return "";
  const MonitorAnalysis& m = *ic.monitor;
  std::string file = std::filesystem::path(m.path).filename().string();
  if (!m.run.loaded || !m.run.created) {
    return "  // " + file + (!m.run.loaded ? " does not load" : "'s create fails") +
           ": YARP passes no message through it;\n"
           "  // the proof takes it as always selected and setting any event\n";
  }
  if (!ic.analysed) return "  // its constraint changes after create: taken as always selected\n";
  if (m.facts.opaque) {
    std::string where =
        m.facts.opaque_line > 0 ? file + ":" + std::to_string(m.facts.opaque_line) : file;
    return "  // " + where + ": " + m.facts.opaque_reason +
           ";\n  // arbc cannot know every event it sets: the proof takes it as setting any "
           "event\n";
  }
  return "";
}

// A `script` rule is opaque to the verifier, so what the monitor provably does before the
// decision (must-set, must-unset) goes into its `when`: the effective guard, which selects the
// same messages at run time (docs/design.md#effective-guards).
std::string rule_text(const YarpImport& im, size_t i, const std::map<std::string, SpecPort>& ports,
                      const std::string& name, const std::string& spec_path) {
  const ImportedConnection& ic = im.connections[i];
  const model::Connection& c = im.app.connections[i];
  Constraint guard = model::effective_guard(im.app, c.destination, c);
  std::string s = unknowns_text(ic);
  if (ic.meaning.parsed && !(c.constraint == ic.meaning.written) &&
      c.kind == model::ConnectionKind::Rule)
    s += "  // written `" + ic.meaning.text + "`: YARP's evaluator selects as below\n";
  if (c.kind == model::ConnectionKind::Feed)
    s += "  // a feed: its accept never returns true, so it only sets events\n";
  if (!(guard == c.constraint))
    s += "  // its monitor sets or unsets events before the decision: selected on `" +
         guard.to_string() + "`\n";
  std::string when = guard.to_string();
  if (!spec_names_ok(guard)) {
    s += "  // constraint `" + ic.meaning.text + "` reads names a spec cannot hold\n";
    when = "false";
  }
  s += "  " + name + ": from " + qualified(ports, c.source);
  if (when != "true") s += " when " + when;
  return s + script_body(ic, spec_path) + "\n";
}

}  // namespace

std::string write_spec(const YarpImport& im, const std::string& spec_path,
                       std::vector<Diagnostic>& renamed) {
  std::map<std::string, SpecPort> ports = spec_port_names(im, renamed);
  std::vector<std::string> rule_names = spec_rule_names(im, renamed);
  std::string s = "// Imported from " + im.xml.file + " by `arbc import yarp` (docs/yarp.md).\n";
  s += "// Rules run the original monitors, written for YARP's Lua API (`script`).\n// Ports:\n";
  for (const auto& [yarp, p] : ports) s += "//   " + yarp + " = " + p.module + "." + p.port + "\n";
  s += "app " + identifier(im.app.name);
  if (!im.app.description.empty()) s += " " + spec_string(im.app.description, true);
  s += ";\n\n// A YARP Bottle holds any values; the spec does not type them.\ntype Bottle = "
       "list<string>;\n\n";
  s += modules_text(ports) + "\n" + events_text(im);
  for (const model::ArbitratedPort& ap : im.app.arbitrated_ports) {
    s += "\narbitrate " + qualified(ports, ap.port) + " {\n";
    for (size_t i = 0; i < im.app.connections.size(); ++i) {
      const model::Connection& c = im.app.connections[i];
      if (c.destination == ap.port) s += rule_text(im, i, ports, rule_names[i], spec_path);
    }
    s += "}\n";
  }
  bool first = true;
  for (size_t i = 0; i < im.app.connections.size(); ++i) {
    const model::Connection& c = im.app.connections[i];
    if (c.kind != model::ConnectionKind::Connect) continue;
    s += std::string(first ? "\n" : "") + "connect " + qualified(ports, c.source) + " -> " +
         qualified(ports, c.destination) + script_body(im.connections[i], spec_path) + "\n";
    first = false;
  }
  return s;
}

}  // namespace arbc::yarp
