#include "verify/structural_checks.h"

#include <algorithm>
#include <map>
#include <set>
#include <span>

#include "core/suggest.h"

namespace arbc::verify {
namespace {

std::set<std::string> events_set_by(const model::Connection& c) {
  std::set<std::string> s(c.sets.begin(), c.sets.end());
  s.insert(c.must_set.begin(), c.must_set.end());
  if (!c.activity_event.empty()) s.insert(c.activity_event);  // set by the runtime on delivery
  return s;
}

std::set<std::string> events_unset_by(const model::Connection& c) {
  std::set<std::string> s(c.unsets.begin(), c.unsets.end());
  s.insert(c.must_unset.begin(), c.must_unset.end());
  return s;
}

// `into` is every connection into the port: looked up once per port, not once per rule.
const model::Connection* find_rule(std::span<const model::Connection* const> into,
                                   const std::string& name) {
  for (const model::Connection* c : into) {
    if (c->name == name && c->kind == model::ConnectionKind::Rule) return c;
  }
  return nullptr;
}

// The events a port reads in its rules' constraints and asserts, each with where it is first
// read (a rule or an assert).
struct Read {
  std::string reader;  // "rule 'take'" or "an assert on 'take'"
  std::string rule;
  model::SourceLocation loc;
};

std::map<std::string, Read> reads_of(const model::App& app, const model::ArbitratedPort& port) {
  std::map<std::string, Read> reads;
  std::vector<const model::Connection*> into = app.connections_into(port.port);
  for (const std::string& name : port.rules) {
    const model::Connection* c = find_rule(into, name);
    if (!c) continue;
    std::set<std::string> events;
    c->constraint.collect_events(events);
    for (const std::string& e : events) reads.emplace(e, Read{"rule '" + name + "'", name, c->loc});
  }
  for (const model::Assertion& a : port.asserts) {
    std::set<std::string> events;
    a.property.collect_events(events);
    for (const std::string& e : events) {
      reads.emplace(e, Read{"the assert on '" + a.rule + "'", a.rule, a.loc});
    }
  }
  return reads;
}

// The fix for an event no rule or assert reads. Removing only its declaration would leave an
// `invariant` or `exclusive` group that mentions it naming an unknown event (an error of
// `arbc check`): the note names those too, each at its line.
void add_unused_event_fix(const model::App& app, const std::string& event, Finding& f) {
  std::vector<Note> mentions;
  size_t invariants = 0;
  for (const model::Invariant& inv : app.invariants) {
    std::set<std::string> events;
    inv.formula.collect_events(events);
    if (!events.count(event)) continue;
    mentions.push_back({"the invariant `" + inv.formula.to_string() + "` mentions it", inv.loc});
    ++invariants;
  }
  for (const model::ExclusiveGroup& g : app.exclusive_groups) {
    if (std::find(g.events.begin(), g.events.end(), event) != g.events.end())
      mentions.push_back({"an exclusive group mentions it", g.loc});
  }
  if (mentions.empty()) {
    f.notes.push_back({"remove it from the event declaration, or use it in a `when`", {}});
    return;
  }
  std::string where = mentions.size() > 1 ? "the invariants and exclusive groups below"
                      : invariants == 1   ? "the invariant below"
                                          : "the exclusive group below";
  f.notes.push_back(
      {"use it in a `when`, or remove it from the event declaration and from " + where, {}});
  f.notes.insert(f.notes.end(), mentions.begin(), mentions.end());
}

using Reads = std::map<std::string, std::map<std::string, Read>>;  // port -> event -> reader

// unfed: per port, each read event must be set by some connection into the port.
void check_unfed(const model::App& app, const Reads& reads, std::vector<Finding>& out) {
  for (const model::ArbitratedPort& port : app.arbitrated_ports) {
    std::set<std::string> fed;
    std::map<std::string, const model::Connection*> setter;  // each fed event's first setter
    bool opaque_feeds = false;  // a `script` monitor may set any event: nothing is provably unfed
    for (const model::Connection* c : app.connections_into(port.port)) {
      std::set<std::string> s = events_set_by(*c);
      fed.insert(s.begin(), s.end());
      for (const std::string& e : s) setter.emplace(e, c);
      opaque_feeds |= c->opaque;
    }
    if (opaque_feeds) continue;
    std::vector<std::string> fed_names(fed.begin(), fed.end());
    for (const auto& [event, read] : reads.at(port.port)) {
      if (fed.count(event)) continue;
      Finding f;
      f.check = kCheckUnfed;
      f.severity = Severity::Error;
      f.port = port.port;
      f.rules = {read.rule};
      f.event = event;
      f.loc = read.loc;
      f.message = read.reader + " of " + port.port + " reads event '" + event +
                  "', but no connection into " + port.port + " sets it, so it is never present";
      // A misspelt event (a constraint `e_bal` where a monitor sets `e_ball`) is the likely
      // cause when a set event is a typo away: say which, and who sets it.
      if (std::optional<std::string> meant = closest_name(event, fed_names)) {
        f.notes.push_back({"did you mean '" + *meant + "'? the connection from " +
                               setter.at(*meant)->source + " sets it",
                           setter.at(*meant)->loc});
      }
      f.notes.push_back({"feed it into the port: `events from M.p { " + event +
                             " }`, a derived event, or `set " + event +
                             "` in a monitor on a connection into " + port.port,
                         {}});
      out.push_back(std::move(f));
    }
  }
}

// unused and ownership, per connection: each event it sets is read by its port's rules or
// asserts, and each event it unsets is one it sets. `reported_unused` gets the unused events.
void check_connection_events(const model::App& app, bool strict, const Reads& reads,
                             std::set<std::string>& reported_unused, std::vector<Finding>& out) {
  for (const model::Connection& c : app.connections) {
    const model::ArbitratedPort* dest = app.find_arbitrated(c.destination);
    std::set<std::string> sets = events_set_by(c);
    for (const std::string& event : sets) {
      if (dest && reads.at(dest->port).count(event)) continue;
      Finding f;
      f.check = kCheckUnused;
      f.severity = strict ? Severity::Error : Severity::Warning;
      f.strict = strict;
      f.strict = strict;
      f.port = dest ? dest->port : "";
      f.rules = {c.name};
      f.event = event;
      f.loc = c.loc;
      f.message = dest ? "connection '" + c.name + "' sets event '" + event +
                             "', but no rule or assert of " + dest->port + " reads it"
                       : "connection '" + c.name + "' sets event '" + event + "', but " +
                             c.destination + " is not arbitrated: it has no event container";
      f.notes.push_back({"remove the set, or read the event in a `when` of " + c.destination, {}});
      reported_unused.insert(event);
      out.push_back(std::move(f));
    }
    for (const std::string& event : events_unset_by(c)) {
      if (sets.count(event)) continue;
      Finding f;
      f.check = kCheckOwnership;
      f.severity = Severity::Error;
      f.port = dest ? dest->port : "";
      f.rules = {c.name};
      f.event = event;
      f.loc = c.loc;
      f.message = "connection '" + c.name + "' unsets event '" + event +
                  "', which it never sets: an unset removes only the connection's own entry, "
                  "so this has no effect";
      f.notes.push_back(
          {"unset the event in the monitor that sets it, or let it expire with a "
           "lifetime",
           {}});
      out.push_back(std::move(f));
    }
  }
}

// unused: an event fed from a stream that no port reads (lowering generates no feed for it).
void check_stream_events(const model::App& app, bool strict, const Reads& reads,
                         const std::set<std::string>& reported_unused, std::vector<Finding>& out) {
  for (const model::Event& e : app.events) {
    if (e.source.empty() || reported_unused.count(e.name)) continue;
    bool read = std::any_of(reads.begin(), reads.end(),
                            [&](const auto& port) { return port.second.count(e.name) > 0; });
    if (read) continue;
    Finding f;
    f.check = kCheckUnused;
    f.severity = strict ? Severity::Error : Severity::Warning;
    f.strict = strict;
    f.event = e.name;
    f.loc = e.loc;
    f.message =
        "event '" + e.name + "' is set from " + e.source + ", but no rule or assert reads it";
    add_unused_event_fix(app, e.name, f);
    out.push_back(std::move(f));
  }
}

}  // namespace

void run_structural_checks(const model::App& app, bool strict, std::vector<Finding>& out) {
  Reads reads;
  for (const model::ArbitratedPort& port : app.arbitrated_ports)
    reads[port.port] = reads_of(app, port);
  check_unfed(app, reads, out);
  std::set<std::string> reported_unused;
  check_connection_events(app, strict, reads, reported_unused, out);
  check_stream_events(app, strict, reads, reported_unused, out);
}

}  // namespace arbc::verify
