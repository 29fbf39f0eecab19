#include "harness/out_port_hint.h"

#include <optional>
#include <vector>

#include "core/suggest.h"

namespace arbc::harness {

namespace {

std::vector<std::string> out_ports(const model::App& app) {
  std::vector<std::string> out;
  for (const model::Module& m : app.modules) {
    for (const model::Port& p : m.ports) {
      if (p.direction == model::Direction::Out) out.push_back(m.name + "." + p.name);
    }
  }
  return out;
}

// A few of the names, so that a long app does not bury the message.
std::string some(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size() && i < 6; ++i) out += (i ? ", " : "") + names[i];
  if (names.size() > 6) out += ", ...";
  return out;
}

}  // namespace

std::string not_an_out_port(const model::App& app, const std::string& port) {
  std::vector<std::string> outs = out_ports(app);
  std::string head = "'" + port + "' is not an out-port of app " + app.name;
  if (app.find_port(port))
    return head + ": it is an in-port (a stand-in publishes on out-ports, such as " + some(outs) +
           ")";
  if (std::optional<std::string> near = closest_name(port, outs))
    return head + "; did you mean '" + *near + "'?";
  if (port.find('.') == std::string::npos) head += "; name a port as Module.port";
  if (outs.empty()) return head;
  return head + " (its out-ports: " + some(outs) + ")";
}

}  // namespace arbc::harness
