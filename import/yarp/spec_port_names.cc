// spec_port_names (spec_names.h): YARP port names as spec modules and ports.
#include <optional>
#include <set>

#include "import/yarp/name_scope.h"
#include "import/yarp/spec_names.h"

namespace arbc::yarp {
namespace {

// A YARP port as the connections name it: where it is first named, and its parts.
struct YarpPort {
  std::string name;
  model::SourceLocation loc;  // its first <from> or <to>
  bool out = false;
  std::string module;  // the YARP module: the name before its last '/' (the whole name if none)
  std::string port;    // the name after it ("" if none)
};

// The ports in the order they are named: every source, then every destination.
std::vector<YarpPort> yarp_ports(const YarpImport& im) {
  std::vector<YarpPort> ports;
  std::set<std::string> seen;
  auto add = [&](const std::string& name, const model::SourceLocation& loc, bool out) {
    if (!seen.insert(name).second) return;
    YarpPort p{name, loc, out, name, ""};
    size_t slash = name.find_last_of('/');
    if (slash != std::string::npos && slash != 0) {
      p.module = name.substr(0, slash);
      p.port = name.substr(slash + 1);
    }
    ports.push_back(std::move(p));
  };
  for (const ImportedConnection& c : im.connections) add(c.xml.from, c.xml.from_loc, true);
  for (const ImportedConnection& c : im.connections) add(c.xml.to, c.xml.to_loc, false);
  return ports;
}

std::string port_base(const YarpPort& p) { return identifier(p.port.empty() ? "port" : p.port); }

Diagnostic renamed_warning(const YarpPort& p, std::string message, const YarpPort& q,
                           std::string said_of_q, const char* fix) {
  Diagnostic d;
  d.severity = Severity::Warning;
  d.loc = p.loc;
  d.id = kIdSpecName;
  d.message = std::move(message);
  d.notes.push_back({Severity::Note, q.loc, std::move(said_of_q), "", {}});
  d.notes.push_back({Severity::Note,
                     {},
                     std::string("spec names hold letters, digits and '_' only: ") + fix,
                     "",
                     {}});
  return d;
}

// The spec module of each YARP module, in the order the ports name them.
std::map<std::string, std::string> module_names(const std::vector<YarpPort>& ports,
                                                std::vector<Diagnostic>& renamed) {
  NameScope scope;
  for (const YarpPort& p : ports) scope.reserve(identifier(p.module));
  std::map<std::string, std::string> names;
  std::vector<size_t> first;  // the port that first names each module, in that order
  for (size_t i = 0; i < ports.size(); ++i) {
    const YarpPort& p = ports[i];
    if (names.count(p.module)) continue;
    std::string base = identifier(p.module);
    std::optional<size_t> holder;
    names[p.module] = scope.give(base, first.size(), &holder);
    first.push_back(i);
    if (!holder) continue;
    const YarpPort& q = ports[first[*holder]];
    renamed.push_back(renamed_warning(
        p,
        "YARP module '" + p.module + "' (of port " + p.name + ") becomes the spec module '" + base +
            "', as does '" + q.module + "' of the port at line " + std::to_string(q.loc.line) +
            ": in the imported spec this module is '" + names[p.module] + "'",
        q, "'" + q.module + "' is the module '" + base + "'",
        "name the ports so that the parts before their last '/' differ in those"));
  }
  return names;
}

}  // namespace

std::map<std::string, SpecPort> spec_port_names(const YarpImport& im,
                                                std::vector<Diagnostic>& renamed) {
  std::vector<YarpPort> ports = yarp_ports(im);
  std::map<std::string, std::string> modules = module_names(ports, renamed);
  std::map<std::string, NameScope> scopes;  // by spec module
  for (const YarpPort& p : ports) scopes[modules.at(p.module)].reserve(port_base(p));
  std::map<std::string, SpecPort> out;
  for (size_t i = 0; i < ports.size(); ++i) {
    const YarpPort& p = ports[i];
    const std::string& module = modules.at(p.module);
    std::string base = port_base(p);
    std::optional<size_t> holder;
    std::string name = scopes[module].give(base, i, &holder);
    out[p.name] = {module, name, p.out};
    if (!holder) continue;
    const YarpPort& q = ports[*holder];
    renamed.push_back(
        renamed_warning(p,
                        "YARP port " + p.name + " becomes the spec port '" + module + "." + base +
                            "', as does " + q.name + " at line " + std::to_string(q.loc.line) +
                            ": in the imported spec it is '" + module + "." + name + "'",
                        q, q.name + " is '" + module + "." + base + "'",
                        "give the ports names that differ in those"));
  }
  return out;
}

}  // namespace arbc::yarp
