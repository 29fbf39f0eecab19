// yarp-shared-event (docs/yarp.md#yarp-shared-event): YARP keeps monitor events in one table
// per process, not per port. An event set by monitors into different ports, or read on one
// port and set only by monitors into others, means one thing if the ports share a process and
// another if they do not; the XML does not say which.
#include <map>
#include <set>

#include "import/yarp/hazards.h"

namespace arbc::yarp {
namespace {

Diagnostic shared_warning(model::SourceLocation loc, std::string message) {
  return make_diagnostic(Severity::Warning, std::move(loc), std::move(message), kIdShared);
}

struct Setter {
  size_t connection;
  model::SourceLocation loc;
};

// event -> destination port -> the first setEvent of it by a monitor into that port.
std::map<std::string, std::map<std::string, Setter>> setters(const YarpImport& im) {
  std::map<std::string, std::map<std::string, Setter>> out;
  for (size_t i = 0; i < im.connections.size(); ++i) {
    const ImportedConnection& ic = im.connections[i];
    if (!ic.monitor || !ic.analysed) continue;
    for (const MonitorCall& c : ic.monitor->facts.calls) {
      if (c.function != "setEvent" || !c.text) continue;
      out[*c.text].emplace(
          ic.xml.to, Setter{i, locate(ic.monitor->path, ic.monitor->text, c.line, "setEvent")});
    }
  }
  return out;
}

std::string ports_text(const std::map<std::string, Setter>& by_port) {
  std::string s;
  for (const auto& [port, setter] : by_port) s += (s.empty() ? "" : ", ") + port;
  return s;
}

// Two or more monitors set the event, one with a lifetime, into one port (several ports are
// reported above): YARP's lookup finds the first entry of a name, and an expired one hides a
// live one once (YarpFacts.AnExpiredEntryHidesALiveOneOnce); each unsetEvent removes only its
// caller's own entry.
void several_setters(const YarpImport& im,
                     const std::map<std::string, std::map<std::string, Setter>>& set_by,
                     std::vector<Diagnostic>& out) {
  for (const auto& [event, by_port] : set_by) {
    if (by_port.size() != 1) continue;
    std::vector<model::SourceLocation> sites;
    bool lifetime = false;
    for (const ImportedConnection& ic : im.connections) {
      if (!ic.monitor || !ic.analysed) continue;
      const MonitorCall* first = nullptr;
      for (const MonitorCall& c : ic.monitor->facts.calls) {
        if (c.function != "setEvent" || c.text != event) continue;
        lifetime |= c.has_second;
        if (!first) first = &c;
      }
      if (first)
        sites.push_back(locate(ic.monitor->path, ic.monitor->text, first->line, "setEvent"));
    }
    if (sites.size() < 2 || !lifetime) continue;
    Diagnostic d =
        shared_warning(sites[0], "event '" + event + "' is set by " + std::to_string(sites.size()) +
                                     " monitors, with a lifetime: when one's entry expires, "
                                     "YARP's next lookup of '" +
                                     event + "' can answer absent although another's is live");
    for (size_t i = 1; i < sites.size(); ++i) add_note(d, "also set here", sites[i]);
    add_note(d,
             "give each event one monitor that sets it (and unsets it: a monitor unsets only "
             "its own entry)");
    out.push_back(std::move(d));
  }
}

}  // namespace

void shared_event_hazards(const YarpImport& im, std::vector<Diagnostic>& out) {
  auto set_by = setters(im);
  for (const auto& [event, by_port] : set_by) {
    if (by_port.size() < 2) continue;
    Diagnostic d =
        shared_warning(by_port.begin()->second.loc,
                       "event '" + event + "' is set by monitors on connections into " +
                           std::to_string(by_port.size()) + " ports (" + ports_text(by_port) +
                           "): YARP keeps events per process, so these ports share it if "
                           "they are in one process, and do not if not");
    for (auto it = std::next(by_port.begin()); it != by_port.end(); ++it)
      add_note(d, "also set for " + it->first, it->second.loc);
    add_note(d, "give each port's events their own names (for example prefix them with the port)");
    out.push_back(std::move(d));
  }
  several_setters(im, set_by, out);
  // Read on a port, set only by monitors into other ports.
  std::set<std::pair<std::string, std::string>> reported;
  for (size_t i = 0; i < im.connections.size(); ++i) {
    const ImportedConnection& ic = im.connections[i];
    const model::Connection& c = im.app.connections[i];
    if (c.kind != model::ConnectionKind::Rule || !ic.monitor || !ic.analysed) continue;
    std::set<std::string> read;
    c.constraint.collect_events(read);
    for (const std::string& e : read) {
      auto it = set_by.find(e);
      if (it == set_by.end() || it->second.count(c.destination) ||
          !reported.insert({c.destination, e}).second)
        continue;
      Diagnostic d = shared_warning(ic.monitor->constraint_loc,
                                    "the constraint of '" + c.name + "' reads '" + e +
                                        "', which only "
                                        "monitors on connections into " +
                                        ports_text(it->second) + " set: this works only if " +
                                        ports_text(it->second) + " and " + c.destination +
                                        " are ports of one process");
      add_note(d, "set here", it->second.begin()->second.loc);
      add_note(d,
               "YARP keeps events per process; put the monitor that sets it on a connection "
               "into " +
                   c.destination +
                   " (a connection whose accept returns false only "
                   "sets events)");
      out.push_back(std::move(d));
    }
  }
}

}  // namespace arbc::yarp
