#include "compiler/docs/graph_docs.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/quote.h"

namespace arbc::docs {

namespace {

std::string module_of(const std::string& qualified) { return qualified.substr(0, qualified.find('.')); }

// Identifiers safe in both DOT and Mermaid.
std::string node_id(const std::string& qualified) {
  std::string id;
  for (char ch : qualified) id += (ch == '.' ? '_' : ch);
  return id;
}

// A DOT string literal.
std::string quoted(const std::string& s) { return arbc::quoted(s, QuoteStyle::Dot); }

}  // namespace

std::string render_dot(const model::App& app) {
  std::ostringstream out;
  out << "digraph " << quoted(app.name) << " {\n"
      << "  rankdir=LR;\n"
      << "  node [shape=box, style=rounded, fontname=\"Helvetica\"];\n"
      << "  edge [fontname=\"Helvetica\", fontsize=10];\n";
  for (const model::Module& m : app.modules) {
    out << "  " << quoted(m.name) << " [label=" << quoted(m.name);
    if (!m.doc.empty()) out << ", tooltip=" << quoted(m.doc);
    out << "];\n";
  }
  // An arbitrated port is a small node in front of its module, labelled with the port name.
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    std::string port_name = p.port.substr(p.port.find('.') + 1);
    out << "  " << node_id(p.port) << " [shape=circle, style=filled, fillcolor=\"#ffe08a\", "
        << "fixedsize=true, width=0.45, fontsize=9, label=\"A\", xlabel=" << quoted(port_name)
        << ", tooltip=" << quoted("arbitrator on " + p.port) << "];\n"
        << "  " << node_id(p.port) << " -> " << quoted(module_of(p.port)) << " [arrowhead=none];\n";
  }
  for (const model::Connection& c : app.connections) {
    std::string target =
        app.find_arbitrated(c.destination) ? node_id(c.destination) : quoted(module_of(c.destination));
    std::string label = c.name;
    if (!c.monitor.empty() && c.kind != model::ConnectionKind::Feed) label += " [M]";
    out << "  " << quoted(module_of(c.source)) << " -> " << target << " [label=" << quoted(label)
        << ", tooltip=" << quoted(c.source + " -> " + c.destination + ": " + c.constraint.to_string());
    if (c.kind == model::ConnectionKind::Feed) out << ", style=dashed, color=\"#777777\"";
    out << "];\n";
  }
  out << "}\n";
  return out.str();
}

std::string render_mermaid(const model::App& app) {
  std::ostringstream out;
  out << "flowchart LR\n";
  for (const model::Module& m : app.modules) out << "  " << node_id(m.name) << "[" << m.name << "]\n";
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    out << "  " << node_id(p.port) << "((\"A " << p.port.substr(p.port.find('.') + 1) << "\"))\n"
        << "  " << node_id(p.port) << " --- " << node_id(module_of(p.port)) << "\n";
  }
  for (const model::Connection& c : app.connections) {
    std::string target = app.find_arbitrated(c.destination) ? node_id(c.destination)
                                                            : node_id(module_of(c.destination));
    std::string label = c.name;
    if (!c.monitor.empty() && c.kind != model::ConnectionKind::Feed) label += " M";
    const char* arrow = c.kind == model::ConnectionKind::Feed ? " -.->|" : " -->|";
    out << "  " << node_id(module_of(c.source)) << arrow << "\"" << label << "\"| " << target << "\n";
  }
  return out.str();
}

bool render_svg(const std::string& dot_text, std::string* svg, std::string* error) {
  // Temporary files keep this free of pipe deadlocks on large graphs.
  char in_path[] = "/tmp/arbc-dot-XXXXXX";
  int fd = mkstemp(in_path);
  if (fd < 0) {
    *error = "cannot create a temporary file for Graphviz";
    return false;
  }
  close(fd);
  std::string out_path = std::string(in_path) + ".svg";
  std::ofstream(in_path) << dot_text;
  std::string command = "dot -Tsvg -o '" + out_path + "' '" + std::string(in_path) + "' 2>/dev/null";
  int status = std::system(command.c_str());
  bool ok = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (ok) {
    std::ifstream in(out_path);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    *svg = buffer.str();
  } else if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    *error = "Graphviz `dot` was not found; install it with `apt-get install graphviz` "
             "(scripts/install-deps.sh does)";
  } else {
    *error = "Graphviz `dot` failed on the generated diagram";
  }
  std::remove(in_path);
  std::remove(out_path.c_str());
  return ok;
}

}  // namespace arbc::docs
