// yarp-port-name (docs/yarp.md#yarp-port-name): a port name in a <from> or <to> that is probably
// misspelt. The XML declares no ports, only the connections between them, so a misspelt name is
// just one more port: the proof takes it as written, and at most yarp-shared-event notices that
// events now cross ports. Two signs of a typo are reported, each with the likely name:
//  - a destination with one connection whose monitor's events link it to a destination with
//    several connections and a close name (that port's rules read what the monitor sets, or the
//    monitor's constraint reads what that port's monitors set): it was meant to go there;
//  - a port whose module (the part before the last '/') is no <module> of the application, when
//    a <module> with a close name has no port in any connection: the module's name is misspelt.
#include <algorithm>
#include <map>
#include <set>

#include "core/join.h"
#include "core/suggest.h"
#include "import/yarp/hazards.h"

namespace arbc::yarp {
namespace {

Diagnostic port_warning(model::SourceLocation loc, std::string message) {
  return make_diagnostic(Severity::Warning, std::move(loc), std::move(message), kIdPortName);
}

std::set<std::string> read_by(const model::Connection& c) {
  std::set<std::string> read;
  c.constraint.collect_events(read);
  return read;
}

std::vector<std::string> common(const std::set<std::string>& read,
                                const std::vector<std::string>& set) {
  std::vector<std::string> out;
  for (const std::string& e : set)
    if (read.count(e)) out.push_back(e);
  return out;
}

std::string lines_text(const YarpImport& im, const std::vector<size_t>& conns) {
  std::string s;
  for (size_t k = 0; k < conns.size(); ++k) {
    s += k == 0 ? "" : k + 1 == conns.size() ? " and " : ", ";
    s += std::to_string(im.connections[conns[k]].xml.loc.line);
  }
  return s;
}

// Why connection i (the only one into its port) belongs to the connections `into` another port:
// "" when nothing links them.
std::string event_link(const YarpImport& im, size_t i, const std::vector<size_t>& into,
                       const std::string& port) {
  const ImportedConnection& ic = im.connections[i];
  if (!ic.monitor || !ic.analysed) return "";
  const model::Connection& c = im.app.connections[i];
  std::set<std::string> fed, wanted;
  std::set<std::string> read = read_by(c);
  for (size_t j : into) {
    const model::Connection& o = im.app.connections[j];
    for (const std::string& e : common(read_by(o), c.sets)) fed.insert(e);
    for (const std::string& e : common(read, o.sets)) wanted.insert(e);
  }
  if (!fed.empty())
    return "its monitor sets " + join(fed) + ", which the rules into " + port + " read";
  if (!wanted.empty())
    return "its constraint reads " + join(wanted) + ", which the monitors into " + port + " set";
  return "";
}

// A destination with one connection, linked by events to a close destination with several.
void misspelt_destinations(const YarpImport& im, std::vector<Diagnostic>& out,
                           std::vector<std::string>& ports, std::set<std::string>& reported) {
  std::map<std::string, std::vector<size_t>> into;
  for (size_t i = 0; i < im.connections.size(); ++i) into[im.connections[i].xml.to].push_back(i);
  std::vector<std::string> crowded;
  for (const auto& [port, conns] : into)
    if (conns.size() >= 2) crowded.push_back(port);
  for (size_t i = 0; i < im.connections.size(); ++i) {
    const XmlConnection& x = im.connections[i].xml;
    if (into[x.to].size() != 1) continue;
    std::optional<std::string> likely = closest_name(x.to, crowded);
    if (!likely) continue;
    std::string why = event_link(im, i, into[*likely], *likely);
    if (why.empty()) continue;
    Diagnostic d = port_warning(x.to_loc, "this is the only connection into " + x.to + ", and " +
                                              why + ": did you mean " + *likely + "?");
    const std::vector<size_t>& there = into[*likely];
    add_note(d, "the connections at lines " + lines_text(im, there) + " go into " + *likely,
             im.connections[there[0]].xml.to_loc);
    add_note(d, "if it is another port, these events reach " + *likely +
                    " only when both ports are in one process (YARP keeps events per process)");
    out.push_back(std::move(d));
    ports.push_back(*likely);
    reported.insert(x.to);
  }
}

std::string module_of(const std::string& port) {
  size_t slash = port.find_last_of('/');
  if (slash == std::string::npos || slash == 0) return "";
  return port.substr(port[0] == '/' ? 1 : 0, slash - (port[0] == '/' ? 1 : 0));
}

// A port of no <module>, close to a <module> that has no port.
void misspelt_modules(const YarpImport& im, std::vector<Diagnostic>& out,
                      std::vector<std::string>& ports, std::set<std::string>& reported) {
  std::set<std::string> listed, with_port;
  for (const XmlModule& m : im.xml.modules) listed.insert(m.name);
  for (const ImportedConnection& ic : im.connections) {
    with_port.insert(module_of(ic.xml.from));
    with_port.insert(module_of(ic.xml.to));
  }
  // Only where the application names its ports after its modules.
  bool named_after_modules = std::any_of(with_port.begin(), with_port.end(),
                                         [&](const std::string& m) { return listed.count(m); });
  if (!named_after_modules) return;
  std::vector<std::string> idle;
  for (const XmlModule& m : im.xml.modules)
    if (!with_port.count(m.name)) idle.push_back(m.name);
  for (const ImportedConnection& ic : im.connections) {
    const XmlConnection& x = ic.xml;
    for (const auto& [port, loc] : {std::pair{x.from, x.from_loc}, std::pair{x.to, x.to_loc}}) {
      std::string module = module_of(port);
      if (module.empty() || listed.count(module) || reported.count(port)) continue;
      std::optional<std::string> likely = closest_name(module, idle);
      if (!likely) continue;
      std::string meant = "/" + *likely + port.substr(port.find_last_of('/'));
      Diagnostic d =
          port_warning(loc, "no <module> is named '" + module + "' (the module of " + port +
                                "), and <module> '" + *likely +
                                "' has no port in any connection: did you mean " + meant + "?");
      for (const XmlModule& m : im.xml.modules)
        if (m.name == *likely) add_note(d, "module '" + *likely + "' is declared here", m.loc);
      out.push_back(std::move(d));
      ports.push_back(x.to);
      reported.insert(port);
    }
  }
}

}  // namespace

void port_name_hazards(const YarpImport& im, std::vector<Diagnostic>& out,
                       std::vector<std::string>& ports) {
  std::set<std::string> reported;
  misspelt_destinations(im, out, ports, reported);
  misspelt_modules(im, out, ports, reported);
}

}  // namespace arbc::yarp
