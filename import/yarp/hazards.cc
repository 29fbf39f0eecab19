// add_hazards and names_collide (hazards.h): the YARP-specific diagnostics of
// docs/yarp.md#diagnostics, each located at the Lua line (or XML line) that causes it.
#include "import/yarp/hazards.h"

#include <cstdio>
#include <map>
#include <set>

#include "core/join.h"

namespace arbc::yarp {
namespace {

constexpr const char* kKeywords[] = {"and", "or", "not", "true", "false"};

model::SourceLocation call_loc(const MonitorAnalysis& m, const MonitorCall& c) {
  return locate(m.path, m.text, c.line, c.function);
}

// Event names joined, "none" when there are none; an empty name (a sample bottle may make a
// script call setEvent("")) is left out.
template <class Names>
std::string names_text(const Names& names) {
  std::vector<std::string> shown;
  for (const std::string& n : names)
    if (!n.empty()) shown.push_back(n);
  return shown.empty() ? "none" : join(shown);
}

std::string verdict_text(const YarpVerdict& v) {
  switch (v.result) {
    case YarpVerdict::Result::True:
      return "true (selected)";
    case YarpVerdict::Result::False:
      return "false (not selected)";
    case YarpVerdict::Result::NotBoolean:
      return "a value that is not a boolean: YARP drops the message, and the value it leaves on "
             "the monitor's Lua stack aborts the receiving process at the next message into "
             "the port";
    case YarpVerdict::Result::LuaError:
      return "a Lua error: YARP drops the message, and the error it leaves on the monitor's Lua "
             "stack hides the monitor's callbacks from then on (" +
             v.error + ")";
  }
  return "?";
}

std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

std::string conn_text(const ImportedConnection& ic, const model::Connection& c) {
  return "'" + c.name + "' (" + ic.xml.from + " -> " + ic.xml.to + ")";
}

// Why YARP's substitution goes wrong: in the witness state when there is one (the first name
// replaced inside a longer word), else the first name that occurs inside another or a keyword.
std::pair<const char*, std::string> collision(const ConstraintMeaning& m) {
  if (m.differs && m.simulated) {
    std::set<std::string> present(m.witness.begin(), m.witness.end());
    Corruption c = first_corruption(m.text, present);
    if (c.found) {
      for (const char* k : kKeywords) {
        if (c.word != k) continue;
        bool written = c.word == "true" || c.word == "false";
        return {kIdKeyword, "`" + c.name + "` is part of `" + c.word + "`" +
                                (written ? ", which YARP wrote for an earlier name," : "") +
                                " and YARP replaces it there too"};
      }
      return {kIdSubstring,
              "`" + c.name + "` is part of `" + c.word + "`, and YARP replaces it there too"};
    }
  }
  for (const std::string& t : m.events) {
    for (const std::string& u : m.events) {
      if (t != u && u.find(t) != std::string::npos)
        return {kIdSubstring, "`" + t + "` is part of `" + u + "`, and YARP replaces it there too"};
    }
  }
  for (const std::string& t : m.events) {
    for (const char* k : kKeywords) {
      if (std::string_view(k).find(t) != std::string_view::npos)
        return {kIdKeyword,
                "`" + t + "` is part of the word `" + k + "`, and YARP replaces it there too"};
    }
  }
  return {kIdSubstring, "YARP replaces names as substrings of the whole text"};
}

void constraint_hazard(const ImportedConnection& ic, const model::Connection& c,
                       std::vector<Diagnostic>& out) {
  const ConstraintMeaning& m = ic.meaning;
  const model::SourceLocation& loc = ic.monitor ? ic.monitor->constraint_loc : ic.xml.protocol_loc;
  if (!m.parsed) {
    Diagnostic d = make_diagnostic(Severity::Error, loc,
                                   "the constraint `" + m.text + "` of " + conn_text(ic, c) +
                                       " does not parse: " + m.parse_error,
                                   kIdConstraintSyntax);
    if (m.simulated) {
      add_note(d, "YARP runs it as Lua after replacing event names: it " +
                      (m.yarp == Constraint::constant(false)
                           ? std::string("never selects the connection")
                           : "selects the connection when " + m.yarp.to_string()));
    }
    add_note(d, "write it with event names, and, or, not, true, false and parentheses");
    out.push_back(std::move(d));
    return;
  }
  bool certain = m.simulated && m.differs;
  if (!certain && (m.simulated || !names_collide(m))) return;
  auto [id, why] = collision(m);
  std::string head = "YARP evaluates the constraint `" + m.text + "` of " + conn_text(ic, c);
  Diagnostic d = make_diagnostic(
      Severity::Error, loc,
      certain ? head + " wrongly: with " + names_text(m.witness) + " present it gives " +
                    verdict_text(m.witness_verdict) + ", but the constraint is " +
                    (m.written_at_witness ? "true" : "false")
              : head + " with too many names to try every state; it may be wrong",
      id);
  add_note(d, why);
  if (certain) {
    add_note(d, "YARP runs: return " + m.witness_verdict.text);
    add_note(d, m.yarp == Constraint::constant(false)
                    ? std::string("so YARP never selects it")
                    : "so YARP selects it when `" + m.yarp.to_string() + "`");
  }
  add_note(d,
           "rename the events so that no name is part of another name or of and, or, not, "
           "true, false (arbc proves what YARP does)");
  out.push_back(std::move(d));
}

void script_call_hazards(const ImportedConnection& ic, std::vector<Diagnostic>& out) {
  const MonitorAnalysis& m = *ic.monitor;
  for (const MonitorCall& c : m.facts.calls) {
    bool event = c.function == "setEvent" || c.function == "unsetEvent";
    if (event && c.text) {
      for (const char* k : kKeywords) {
        if (*c.text != k) continue;
        Diagnostic d = make_diagnostic(Severity::Error, call_loc(m, c),
                                       "YARP ignores PortMonitor." + c.function + "(\"" + *c.text +
                                           "\"): an event named like a keyword is never set",
                                       kIdKeyword);
        add_note(d, "rename the event (for example e_" + *c.text + ")");
        out.push_back(std::move(d));
      }
    }
    if (c.function != "setTrigInterval") continue;
    std::string arg = c.number ? number_text(*c.number) : "x";
    std::string period =
        c.number ? std::to_string(static_cast<long>(*c.number * 1000)) + " s" : "1000 x s";
    Diagnostic d =
        make_diagnostic(Severity::Warning, call_loc(m, c),
                        "PortMonitor.setTrigInterval(" + arg + ") makes YARP call trig every " +
                            period + ", not every " + arg + " s",
                        kIdTrigInterval);
    add_note(d, "YARP 3.12 starts the trigger thread with a period of (int)(" + arg +
                    " * 1000) seconds (MonitorLua::setTrigInterval)");
    add_note(d,
             "do periodic work in accept or trig from yarp.now() timestamps: YARP calls trig "
             "whenever a message arrives on another connection into the same port");
    out.push_back(std::move(d));
  }
}

// setEvent(e) without a lifetime, and no unsetEvent(e) on a message path of the same script.
void forever_hazards(const YarpImport& im, size_t i, std::vector<Diagnostic>& out) {
  const MonitorAnalysis& m = *im.connections[i].monitor;
  std::set<std::string> unset_here, reported;
  for (const MonitorCall& c : m.facts.calls) {
    if (c.function == "unsetEvent" && c.text && c.callback != "destroy" && !c.callback.empty())
      unset_here.insert(*c.text);
  }
  for (const MonitorCall& c : m.facts.calls) {
    bool forever =
        c.function == "setEvent" && c.text && (!c.has_second || (c.number && *c.number < 0));
    if (!forever || unset_here.count(*c.text) || !reported.insert(*c.text).second) continue;
    Diagnostic d =
        make_diagnostic(Severity::Warning, call_loc(m, c),
                        "event '" + *c.text + "' is set without a lifetime and " +
                            conn_text(im.connections[i], im.app.connections[i]) +
                            " never unsets it: once set, it stays until the receiving process "
                            "exits",
                        kIdForever);
    for (size_t j = 0; j < im.connections.size(); ++j) {
      if (j == i || !im.connections[j].monitor) continue;
      for (const MonitorCall& u : im.connections[j].monitor->facts.calls) {
        if (u.function == "unsetEvent" && u.text == c.text)
          add_note(d,
                   "this unsetEvent has no effect on it: YARP removes only the caller's own "
                   "copy of an event",
                   call_loc(*im.connections[j].monitor, u));
      }
    }
    add_note(d, "give it a lifetime, PortMonitor.setEvent(\"" + *c.text +
                    "\", 0.5), or unset it in this monitor");
    out.push_back(std::move(d));
  }
}

void opaque_hazard(const ImportedConnection& ic, const model::Connection& c,
                   std::vector<Diagnostic>& out) {
  const MonitorAnalysis& m = *ic.monitor;
  model::SourceLocation loc =
      m.facts.opaque_line > 0 ? locate(m.path, m.text, m.facts.opaque_line, m.facts.opaque_token)
                              : model::SourceLocation{m.path, 0, 0, 0, 0};
  Diagnostic d = make_diagnostic(Severity::Warning, loc,
                                 "arbc cannot know every event " + conn_text(ic, c) +
                                     " sets: " + m.facts.opaque_reason +
                                     "; the proof takes it as possibly setting any "
                                     "event",
                                 kIdOpaque);
  if (!m.observed_sets.empty()) {
    add_note(d, "on sample bottles it set: " + names_text(m.observed_sets));
  }
  add_note(d, "pass event names to PortMonitor.setEvent / unsetEvent as string literals");
  out.push_back(std::move(d));
}

}  // namespace

bool names_collide(const ConstraintMeaning& m) {
  for (const std::string& t : m.events) {
    for (const std::string& u : m.events) {
      if (t != u && u.find(t) != std::string::npos) return true;
    }
    for (const char* k : kKeywords) {
      if (std::string_view(k).find(t) != std::string_view::npos) return true;
    }
  }
  return false;
}

void shared_event_hazards(const YarpImport& im, std::vector<Diagnostic>& out);
void port_name_hazards(const YarpImport& im, std::vector<Diagnostic>& out,
                       std::vector<std::string>& ports);

void add_hazards(YarpImport& im) {
  // A misspelt port comes first: the shared events and the port verdicts follow from it.
  std::vector<Diagnostic> typos;
  std::vector<std::string> typo_ports;
  port_name_hazards(im, typos, typo_ports);
  for (size_t k = 0; k < typos.size(); ++k) {
    im.diagnostics.push_back(std::move(typos[k]));
    im.diagnostic_ports.push_back(typo_ports[k]);
  }
  std::vector<Diagnostic> out;
  for (size_t i = 0; i < im.connections.size(); ++i) {
    const ImportedConnection& ic = im.connections[i];
    if (!ic.analysed || !ic.monitor) continue;
    if (ic.monitor->has_constraint) {
      std::vector<Diagnostic> about_port;
      constraint_hazard(ic, im.app.connections[i], about_port);
      // A wrong constraint is about the destination port: it joins that port's findings.
      for (Diagnostic& d : about_port) {
        im.diagnostics.push_back(std::move(d));
        im.diagnostic_ports.push_back(ic.xml.to);
      }
    }
    script_call_hazards(ic, out);
    forever_hazards(im, i, out);
    if (ic.monitor->facts.opaque) opaque_hazard(ic, im.app.connections[i], out);
  }
  shared_event_hazards(im, out);
  for (Diagnostic& d : out) {
    im.diagnostics.push_back(std::move(d));
    im.diagnostic_ports.emplace_back();
  }
}

}  // namespace arbc::yarp
