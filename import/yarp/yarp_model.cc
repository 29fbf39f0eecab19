// import_yarp (yarp_import.h): the XML and its monitors as the core model.
#include <algorithm>
#include <map>
#include <set>

#include "import/yarp/connection_import.h"
#include "import/yarp/hazards.h"
#include "import/yarp/yarp_import.h"

namespace arbc::yarp {
namespace {

std::vector<std::string> sorted(const std::set<std::string>& s) { return {s.begin(), s.end()}; }

// What the proof selects on: YARP's answers when every state was tried, else the written
// constraint when no name can hit another, else `true` (always selected: sound, may refute).
Constraint model_constraint(const ImportedConnection& ic) {
  const ConstraintMeaning& m = ic.meaning;
  if (!ic.analysed) return Constraint::constant(true);
  if (m.simulated) return m.differs ? m.yarp : m.written;
  if (m.parsed && !names_collide(m)) return m.written;
  return Constraint::constant(true);
}

// The rule name: the connection's id, else its monitor's file, else its source port's last
// part; made unique within the destination port (`taken`: each name given there, with the
// connection it was given to). An id that has to change is a warning: the XML says one name
// and the verdicts and the imported spec another.
std::string rule_name(const YarpImport& im, size_t i, std::map<std::string, size_t>& taken,
                      std::vector<Diagnostic>& diags) {
  const ImportedConnection& ic = im.connections[i];
  std::string base = ic.xml.id;
  if (base.empty() && ic.carrier.monitor) base = ic.carrier.file;
  if (base.empty()) {
    base = ic.xml.from.substr(ic.xml.from.find_last_of('/') + 1);
    if (base.empty()) base = ic.xml.from;
  }
  std::string name = base;
  for (int k = 2; taken.count(name); ++k) name = base + "_" + std::to_string(k);
  if (name != base && !ic.xml.id.empty()) {
    const XmlConnection& first = im.connections[taken.at(base)].xml;
    std::string by = first.id == base ? "the id of the connection at line "
                                      : "the name arbc gave the connection at line ";
    Diagnostic d;
    d.severity = Severity::Warning;
    d.loc = ic.xml.id_loc;
    d.id = kIdDuplicateId;
    d.message = "connection id '" + base + "' into " + ic.xml.to + " is already " + by +
                std::to_string(first.loc.line) + ": this connection's rule is named '" + name + "'";
    d.notes.push_back({Severity::Note, first.id_loc, "first used here", "", {}});
    d.notes.push_back({Severity::Note,
                       {},
                       "give each connection into a port its own id (the verdicts and `arbc "
                       "import yarp` name rules after them)",
                       "",
                       {}});
    diags.push_back(std::move(d));
  }
  taken.emplace(name, i);
  return name;
}

model::Connection model_connection(const ImportedConnection& ic) {
  model::Connection c;
  c.source = ic.xml.from;
  c.destination = ic.xml.to;
  c.constraint = model_constraint(ic);
  c.loc = ic.xml.loc;
  c.opaque = !ic.analysed;
  if (ic.monitor) {
    const MonitorAnalysis& m = *ic.monitor;
    c.monitor = m.path;
    std::set<std::string> sets = m.facts.sets(), unsets = m.facts.unsets();
    // Names seen on samples are reported (yarp-opaque), never taken as all it can set.
    if (m.facts.opaque) c.opaque = true;
    c.sets = sorted(sets);
    c.unsets = sorted(unsets);
    if (!c.opaque && m.facts.paths_ok && m.facts.callbacks.count("accept")) {
      c.must_set = sorted(m.facts.must_set);
      c.must_unset = sorted(m.facts.must_unset);
    }
    if (!c.opaque && m.facts.paths_ok && m.facts.delivery_set.size() == 1)
      c.activity_event = *m.facts.delivery_set.begin();
  }
  return c;
}

// A connection whose accept provably never returns a true value never delivers: a feed. A
// monitor whose event names are computed can be one too (it still sets any event).
bool never_delivers(const ImportedConnection& ic) {
  if (!ic.analysed || !ic.monitor) return false;
  const ScriptFacts& f = ic.monitor->facts;
  bool returns_known = f.paths_ok || (f.opaque && f.opaque_names_only);
  return returns_known && f.callbacks.count("accept") && !f.accept_may_accept;
}

// YARP: unsetEvent removes only the caller's own copy of an event. So "this monitor unsets e"
// makes e absent only when no other monitor sets e.
void restrict_must_unset(model::App& app) {
  for (size_t i = 0; i < app.connections.size(); ++i) {
    std::vector<std::string> kept;
    for (const std::string& e : app.connections[i].must_unset) {
      bool elsewhere = false;
      for (size_t j = 0; j < app.connections.size(); ++j) {
        const model::Connection& o = app.connections[j];
        elsewhere |= j != i && (o.opaque || std::count(o.sets.begin(), o.sets.end(), e));
      }
      if (!elsewhere) kept.push_back(e);
    }
    app.connections[i].must_unset = std::move(kept);
  }
}

// An activity event (set by update as the connection delivers) counts only when no other
// monitor into the port sets it: otherwise it is present without this connection delivering.
void restrict_activity_events(model::App& app) {
  for (model::Connection& c : app.connections) {
    if (c.activity_event.empty()) continue;
    for (const model::Connection& o : app.connections) {
      if (&o == &c || o.destination != c.destination) continue;
      if (o.opaque || std::count(o.sets.begin(), o.sets.end(), c.activity_event))
        c.activity_event.clear();
    }
  }
}

void arbitrated_ports(YarpImport& im) {
  model::App& app = im.app;
  std::map<std::string, std::vector<size_t>> into;
  std::vector<std::string> order;
  for (size_t i = 0; i < app.connections.size(); ++i) {
    const std::string& to = app.connections[i].destination;
    if (!into.count(to)) order.push_back(to);
    into[to].push_back(i);
  }
  for (const std::string& port : order) {
    const std::vector<size_t>& conns = into[port];
    bool constrained = std::any_of(conns.begin(), conns.end(), [&](size_t i) {
      return !im.connections[i].meaning.text.empty();
    });
    std::map<std::string, size_t> taken;
    model::ArbitratedPort ap;
    ap.port = port;
    ap.loc = app.connections[conns[0]].loc;
    for (size_t i : conns) {
      model::Connection& c = app.connections[i];
      c.name = rule_name(im, i, taken, im.diagnostics);
      im.diagnostic_ports.resize(im.diagnostics.size(), port);
      c.kind = model::ConnectionKind::Connect;
      if (conns.size() < 2 && !constrained) continue;
      if (never_delivers(im.connections[i])) {
        c.kind = model::ConnectionKind::Feed;
        c.constraint = Constraint::constant(false);
        continue;
      }
      c.kind = model::ConnectionKind::Rule;
      ap.rules.push_back(c.name);
    }
    if (conns.size() >= 2 || constrained) app.arbitrated_ports.push_back(std::move(ap));
  }
}

// The events the app names, with a lifetime when every setEvent of it gives the same one.
void collect_events(YarpImport& im) {
  std::map<std::string, std::set<Nanos>> lifetimes;
  std::set<std::string> forever, names;
  for (size_t i = 0; i < im.connections.size(); ++i) {
    const model::Connection& c = im.app.connections[i];
    names.insert(c.sets.begin(), c.sets.end());
    names.insert(c.unsets.begin(), c.unsets.end());
    std::set<std::string> read;
    c.constraint.collect_events(read);
    names.insert(read.begin(), read.end());
    if (!im.connections[i].monitor) continue;
    for (const MonitorCall& call : im.connections[i].monitor->facts.calls) {
      if (call.function != "setEvent" || !call.text) continue;
      if (call.number && *call.number > 0) {
        // To the nanosecond, the runtime's unit (core/instant.h), and no longer than a spec
        // may write.
        lifetimes[*call.text].insert(std::min(nanos_from_seconds(*call.number), kLongestDuration));
      } else {
        forever.insert(*call.text);
      }
    }
  }
  for (const std::string& n : names) {
    model::Event e;
    e.name = n;
    if (!forever.count(n) && lifetimes[n].size() == 1) e.lifetime = *lifetimes[n].begin();
    im.app.events.push_back(std::move(e));
  }
}

}  // namespace

YarpImport import_yarp(const std::string& xml_path, const YarpImportOptions& options) {
  YarpImport im;
  std::optional<XmlApplication> xml = read_application_xml(xml_path, im.diagnostics);
  if (!xml) return im;
  im.xml = std::move(*xml);
  std::unique_ptr<YarpEvaluator> evaluator = YarpEvaluator::create();
  if (!evaluator) {
    im.diagnostics.push_back(
        {Severity::Error, {xml_path}, "cannot create a Lua state", kIdXml, {}});
    return im;
  }
  bool bad_input = false;
  im.diagnostic_ports.resize(im.diagnostics.size());
  for (const XmlConnection& c : im.xml.connections) {
    im.connections.push_back(
        import_connection(c, xml_path, options, *evaluator, im.diagnostics, bad_input));
    im.diagnostic_ports.resize(im.diagnostics.size(), c.to);
  }
  if (bad_input) return im;
  im.app.name = im.xml.name;
  im.app.description = im.xml.description;
  im.app.spec_file = xml_path;
  for (const ImportedConnection& ic : im.connections)
    im.app.connections.push_back(model_connection(ic));
  restrict_must_unset(im.app);
  restrict_activity_events(im.app);
  arbitrated_ports(im);
  derive_exclusive_groups(im);
  collect_events(im);
  add_hazards(im);
  im.ok = true;
  return im;
}

}  // namespace arbc::yarp
