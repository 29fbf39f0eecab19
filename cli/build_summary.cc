#include "cli/build_summary.h"

#include <algorithm>
#include <vector>

#include "compiler/codegen/yarp_checks.h"
#include "core/join.h"

namespace arbc::cli {

namespace {

std::string pad(std::string s, size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

}  // namespace

std::string build_summary(const model::App& app, const std::string& spec,
                          const std::string& out_dir, const std::string& verified) {
  size_t written = 0, generated = 0, name_w = 4, source_w = 6;
  std::vector<std::string> ports;  // destinations in first-seen order
  for (const model::Connection& c : app.connections) {
    (c.generated ? generated : written) += 1;
    name_w = std::max(name_w, c.name.size());
    source_w = std::max(source_w, c.source.size());
    if (std::find(ports.begin(), ports.end(), c.destination) == ports.end())
      ports.push_back(c.destination);
  }
  std::string dir = out_dir + "/" + app.name;
  std::string out = "arbc build: " + spec + " -> " + dir + "/\n";
  out += "  " + verified + "\n";
  out += "  app.json and " + count_of(app.connections.size(), "monitor", "monitors") + ": " +
         count_of(written, "connection", "connections") + " you wrote, " +
         std::to_string(generated) + " generated\n";
  for (const std::string& port : ports) {
    bool arbitrated = app.find_arbitrated(port) != nullptr;
    out += "\n  " + port + (arbitrated ? " (arbitrated)" : "") + "\n";
    for (const model::Connection& c : app.connections) {
      if (c.destination != port) continue;
      std::string what;
      switch (c.kind) {
        case model::ConnectionKind::Rule:
          what = "rule, yours";
          break;
        case model::ConnectionKind::Connect:
          what = "connect, yours";
          break;
        case model::ConnectionKind::Feed:
          what = "feed, generated: " + join(c.sets);
          break;
      }
      out += "    " + pad(c.name, name_w) + "  <- " + pad(c.source, source_w) + "  " + what + "\n";
    }
  }
  return out;
}

std::string yarp_build_summary(const model::App& app, const std::string& spec,
                               const std::string& out_dir, const std::string& verified,
                               const std::vector<std::string>& files) {
  size_t monitors = 0;
  for (const std::string& f : files) monitors += f.rfind("contexts/", 0) == 0 ? 1 : 0;
  std::string dir = out_dir + "/" + app.name;
  std::string out = "arbc build: " + spec + " -> " + dir + "/ (YARP)\n";
  out += "  " + verified + "\n";
  out += "  " + app.name + ".xml, ports.json and " +
         count_of(monitors, "YARP monitor", "YARP monitors") + " for " +
         count_of(app.connections.size(), "connection", "connections") +
         " (connections that share a source and a destination are one YARP connection)\n";
  // What the monitors check at run time of the proof, and what no YARP monitor can.
  std::vector<std::string> checked = codegen::yarp_checked(app);
  std::vector<std::string> unchecked = codegen::yarp_unchecked(app);
  if (!checked.empty())
    out += "  runtime checks in the monitors: " + join(checked) +
           ", said on the receiving process's stderr\n";
  if (!unchecked.empty())
    out += "  not checked at run time on YARP (its monitors cannot read a port's events): " +
           join(unchecked) + "; docs/yarp.md#runtime-checks\n";
  out += "  next: fill in the modules of " + app.name +
         ".xml; docs/yarp.md#deploying-a-spec-on-yarp-step-by-step\n";
  return out;
}

}  // namespace arbc::cli
