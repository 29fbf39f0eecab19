#include "compiler/docs/graph_docs.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "compiler/docs/port_summary.h"
#include "core/duration_literal.h"
#include "core/join.h"
#include "core/quote.h"

namespace arbc::docs {

namespace {

// Constraint text wider than this wraps, so an arbitrator box stays narrow.
constexpr size_t kWrapColumns = 44;

using Index = std::map<std::string, std::vector<const model::Connection*>, std::less<>>;

std::string module_of(const std::string& qualified) {
  return qualified.substr(0, qualified.find('.'));
}

// Identifiers safe in both DOT and Mermaid.
std::string node_id(const std::string& qualified) {
  std::string id;
  for (char ch : qualified) id += (ch == '.' ? '_' : ch);
  return id;
}

// A DOT string literal.
std::string quoted(const std::string& s) { return arbc::quoted(s, QuoteStyle::Dot); }

// Text inside a Graphviz HTML-like label.
std::string html(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '&')
      out += "&amp;";
    else if (ch == '<')
      out += "&lt;";
    else if (ch == '>')
      out += "&gt;";
    else if (ch == '"')
      out += "&quot;";
    else
      out += ch;
  }
  return out;
}

// Splits `text` at spaces into lines of at most kWrapColumns (a longer word stays whole).
std::vector<std::string> wrap(const std::string& text) {
  std::vector<std::string> lines{""};
  std::istringstream words(text);
  for (std::string w; words >> w;) {
    if (!lines.back().empty() && lines.back().size() + 1 + w.size() > kWrapColumns)
      lines.emplace_back();
    lines.back() += (lines.back().empty() ? "" : " ") + w;
  }
  return lines;
}

// As the spec writes the time (`hold 1s`, `throttle 500ms`).
std::string seconds(Nanos d) { return duration_literal(d); }

// One line of an arbitrator's rule list: "take: when ...", "1 track: when ..., hold 1 s".
std::string rule_line(const PortSummary& p, size_t k) {
  const RuleSummary& r = p.rules[k];
  std::string line = p.port->by_priority ? std::to_string(k + 1) + " " : "";
  line += r.connection->name + ": when " + r.when;
  if (r.hold) line += ", hold " + seconds(*r.hold);
  if (!r.sets.empty()) line += ", sets " + join(r.sets, ", ");
  return line;
}

Index connections_by_destination(const model::App& app) {
  Index index;
  for (const model::Connection& c : app.connections) index[c.destination].push_back(&c);
  return index;
}

std::vector<PortSummary> summaries(const model::App& app, const Index& into) {
  static const std::vector<const model::Connection*> kNone;
  std::vector<PortSummary> out;
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    auto it = into.find(p.port);
    out.push_back(summarize_port(app, p, it == into.end() ? kNone : it->second));
  }
  return out;
}

// The arbitrator box: a header naming the port, a row per rule, a row per feed.
std::string arbitrator_label(const PortSummary& p) {
  std::ostringstream out;
  out << "<<TABLE BORDER=\"1\" CELLBORDER=\"0\" CELLSPACING=\"0\" CELLPADDING=\"3\" "
         "COLOR=\"#a08000\" BGCOLOR=\"#fff8dc\">"
      << "<TR><TD COLSPAN=\"2\" BGCOLOR=\"#ffe08a\" ALIGN=\"LEFT\"><B>A " << html(p.port->port)
      << "</B>" << (p.port->by_priority ? " by priority, highest first" : "")
      << (p.port->complete ? " (complete)" : "") << "</TD></TR>";
  for (size_t k = 0; k < p.rules.size(); ++k) {
    const RuleSummary& r = p.rules[k];
    std::string name =
        (p.port->by_priority ? std::to_string(k + 1) + " " : "") + r.connection->name;
    std::vector<std::string> lines = wrap("when " + r.when);
    if (r.hold) lines.push_back("hold " + seconds(*r.hold));
    if (!r.sets.empty()) {
      std::vector<std::string> more = wrap("sets " + join(r.sets, ", "));
      lines.insert(lines.end(), more.begin(), more.end());
    }
    for (std::string& l : lines) l = html(l);
    out << "<TR><TD PORT=\"r" << k << "\" ALIGN=\"LEFT\" VALIGN=\"TOP\"><B>" << html(name)
        << "</B></TD><TD ALIGN=\"LEFT\" BALIGN=\"LEFT\">" << join(lines, "<BR/>") << "</TD></TR>";
  }
  for (size_t k = 0; k < p.feeds.size(); ++k) {
    std::vector<std::string> lines = wrap(
        (p.feeds[k].delivered ? "events from what " + p.feeds[k].connection->source + " delivers: "
                              : "events from " + p.feeds[k].connection->source + ": ") +
        join(p.feeds[k].events, ", "));
    for (std::string& l : lines) l = html(l);
    out << "<TR><TD PORT=\"f" << k << "\" COLSPAN=\"2\" ALIGN=\"LEFT\" BALIGN=\"LEFT\">"
        << "<FONT COLOR=\"#555555\">" << join(lines, "<BR/>") << "</FONT></TD></TR>";
  }
  out << "</TABLE>>";
  return out.str();
}

void dot_arbitrator(const PortSummary& p, std::ostream& out) {
  std::string id = node_id(p.port->port);
  out << "  " << id << " [shape=plain, label=" << arbitrator_label(p)
      << ", tooltip=" << quoted("arbitrator on " + p.port->port) << "];\n"
      << "  " << id << " -> " << quoted(module_of(p.port->port)) << ";\n";
  for (size_t k = 0; k < p.rules.size(); ++k) {
    const model::Connection& c = *p.rules[k].connection;
    out << "  " << quoted(module_of(c.source)) << " -> " << id << ":r" << k << ":w [tooltip="
        << quoted(c.name + ": " + c.source + " -> " + c.destination + " when " +
                  c.constraint.to_string())
        << "];\n";
  }
  for (size_t k = 0; k < p.feeds.size(); ++k) {
    const model::Connection& c = *p.feeds[k].connection;
    out << "  " << quoted(module_of(c.source)) << " -> " << id << ":f" << k
        << " [style=dashed, color=\"#888888\", constraint=false, tooltip="
        << quoted(c.name + ": " + c.source + " -> " + c.destination) << "];\n";
  }
}

// What the drawing's marks mean, for the marks it has.
std::string legend(const model::App& app) {
  bool feeds = false, monitored_connects = false;
  for (const model::Connection& c : app.connections) {
    feeds |= c.kind == model::ConnectionKind::Feed;
    monitored_connects |= c.kind == model::ConnectionKind::Connect && !c.monitor.empty();
  }
  std::vector<std::string> parts;
  if (!app.arbitrated_ports.empty())
    parts.push_back(
        "A: an arbitrated port; a message reaches it only through a rule whose "
        "when holds");
  if (feeds) parts.push_back("dashed: event feeds generated by arbc");
  if (monitored_connects) parts.push_back("[M]: a monitored connection");
  return join(parts, "; ");
}

}  // namespace

size_t diagram_elements(const model::App& app) {
  return app.modules.size() + app.arbitrated_ports.size() + app.connections.size();
}

std::string render_dot(const model::App& app) {
  std::ostringstream out;
  out << "digraph " << quoted(app.name) << " {\n"
      << "  graph [rankdir=LR, nodesep=0.25, ranksep=0.5, fontname=\"Helvetica\", fontsize=10, "
         "labelloc=b, labeljust=l, label="
      << quoted(legend(app)) << "];\n"
      << "  node [shape=box, style=rounded, fontname=\"Helvetica\", fontsize=11];\n"
      << "  edge [fontname=\"Helvetica\", fontsize=10, arrowsize=0.7];\n";
  for (const model::Module& m : app.modules) {
    out << "  " << quoted(m.name) << " [label=" << quoted(m.name);
    if (!m.doc.empty()) out << ", tooltip=" << quoted(m.doc);
    out << "];\n";
  }
  Index into = connections_by_destination(app);
  for (const PortSummary& p : summaries(app, into)) dot_arbitrator(p, out);
  // Connections into ports that are not arbitrated: plain edges between modules.
  for (const model::Connection& c : app.connections) {
    if (c.kind != model::ConnectionKind::Connect) continue;
    out << "  " << quoted(module_of(c.source)) << " -> " << quoted(module_of(c.destination))
        << " [label=" << quoted(c.monitor.empty() ? "" : "[M]")
        << ", tooltip=" << quoted(c.source + " -> " + c.destination) << "];\n";
  }
  out << "}\n";
  return out.str();
}

std::string render_mermaid(const model::App& app) {
  std::ostringstream out;
  out << "flowchart LR\n";
  for (const model::Module& m : app.modules)
    out << "  " << node_id(m.name) << "[" << m.name << "]\n";
  Index into = connections_by_destination(app);
  for (const PortSummary& p : summaries(app, into)) {
    std::string id = node_id(p.port->port);
    std::vector<std::string> lines{"A " + p.port->port +
                                   (p.port->by_priority ? " by priority" : "")};
    for (size_t k = 0; k < p.rules.size(); ++k) lines.push_back(rule_line(p, k));
    out << "  " << id << "[[\"" << join(lines, "<br/>") << "\"]]\n"
        << "  " << id << " --> " << node_id(module_of(p.port->port)) << "\n";
    for (const RuleSummary& r : p.rules)
      out << "  " << node_id(module_of(r.connection->source)) << " -->|" << r.connection->name
          << "| " << id << "\n";
    for (const FeedSummary& f : p.feeds)
      out << "  " << node_id(module_of(f.connection->source)) << " -.->|\"" << join(f.events, ", ")
          << "\"| " << id << "\n";
  }
  for (const model::Connection& c : app.connections) {
    if (c.kind != model::ConnectionKind::Connect) continue;
    out << "  " << node_id(module_of(c.source)) << " -->" << (c.monitor.empty() ? "" : "|\"[M]\"|")
        << " " << node_id(module_of(c.destination)) << "\n";
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
  std::string command =
      "dot -Tsvg -o '" + out_path + "' '" + std::string(in_path) + "' 2>/dev/null";
  int status = std::system(command.c_str());
  bool ok = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (ok) {
    std::ifstream in(out_path);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    *svg = buffer.str();
  } else if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 127) {
    *error =
        "Graphviz `dot` was not found; install it with `apt-get install graphviz` "
        "(scripts/install-deps.sh does)";
  } else {
    *error = "Graphviz `dot` failed on the generated diagram";
  }
  std::remove(in_path);
  std::remove(out_path.c_str());
  return ok;
}

}  // namespace arbc::docs
