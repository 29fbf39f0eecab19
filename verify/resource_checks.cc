#include "verify/resource_checks.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "core/join.h"
#include "verify/data_pair.h"

namespace arbc::verify {

namespace {

// A rule into one of the resource's ports.
struct ResourceRule {
  const model::Connection* connection = nullptr;
  size_t port = 0;  // index into the resource's ports
  const PortScope* scope = nullptr;
  const ScopedRule* rule = nullptr;
  int index = 0;  // in its port's scope
};

// Two ports' rules over one event state: the union of both scopes and domains (an event name is
// one fact for the resource, docs/checks.md#resource). Rules: the first port's, then the second's.
PortScope joint_scope(const PortScope& a, const PortScope& b) {
  PortScope j;
  j.port = a.port;
  j.rules = a.rules;
  j.rules.insert(j.rules.end(), b.rules.begin(), b.rules.end());
  j.events = a.events;
  j.events.insert(j.events.end(), b.events.begin(), b.events.end());
  std::sort(j.events.begin(), j.events.end());
  j.events.erase(std::unique(j.events.begin(), j.events.end()), j.events.end());
  j.domain = a.domain;
  for (const DomainConstraint& d : b.domain) {
    bool known = false;
    for (const DomainConstraint& e : j.domain) known |= e.text == d.text;
    if (!known) j.domain.push_back(d);
  }
  return j;
}

// The event side of every pair of rules of two ports, decided by one solver over their joint
// scope: a few queries for all pairs, where one solver per pair of rules cost milliseconds each.
struct PortPair {
  PortScope scope;
  std::unique_ptr<PortSolver> solver;
  int first_rules = 0;                        // rules of the first port (joint indices below)
  std::set<std::pair<int, int>> overlapping;  // pairs selected together in some state
  bool undecided = false;                     // the solver gave no answer: every pair may overlap
};

class ResourceChecker {
 public:
  ResourceChecker(const model::App& app, const std::vector<PortScope>& scopes,
                  const VerifyOptions& options, z3::context& ctx, Clock::time_point deadline,
                  DataQuery& data, const model::Resource& res, ResourceResult& out)
      : app_(app),
        scopes_(scopes),
        options_(options),
        ctx_(ctx),
        deadline_(deadline),
        data_(data),
        res_(res),
        out_(out) {}

  void run() {
    out_.name = res_.name;
    out_.ports = res_.ports;
    out_.loc = res_.loc;
    std::vector<ResourceRule> rules = resource_rules();
    for (size_t i = 0; i < rules.size(); ++i)
      for (size_t j = i + 1; j < rules.size(); ++j)
        if (rules[i].port != rules[j].port) check_pair(rules[i], rules[j]);
    bool error = false;
    for (const Finding& f : out_.findings)
      error |= f.severity == Severity::Error && f.check != kCheckUnknown;
    out_.verdict = error                          ? Verdict::Refuted
                   : !out_.unknown_reason.empty() ? Verdict::Unknown
                                                  : Verdict::Proved;
  }

  // The rules into the resource's ports.
  std::vector<ResourceRule> resource_rules() {
    std::vector<ResourceRule> out;
    for (size_t p = 0; p < res_.ports.size(); ++p) {
      for (const PortScope& s : scopes_) {
        if (s.port->port != res_.ports[p]) continue;
        for (const ScopedRule& r : s.rules)
          out.push_back({r.connection, p, &s, &r, static_cast<int>(&r - s.rules.data())});
      }
    }
    return out;
  }

  void unknown(const std::string& what, const std::string& reason) {
    if (!out_.unknown_reason.empty()) return;
    out_.unknown_reason = reason;
    Finding f = base_finding(kCheckUnknown);
    f.message = "could not decide " + what + " for resource '" + res_.name + "' (" + reason +
                "); an unknown verdict never passes";
    out_.findings.push_back(std::move(f));
  }

  Finding base_finding(const char* check) const {
    Finding f;
    f.check = check;
    f.severity = Severity::Error;
    f.loc = res_.loc;
    return f;
  }

  std::string pair_name(const ResourceRule& a, const ResourceRule& b) const {
    return "'" + a.connection->name + "' (into " + res_.ports[a.port] + ") and '" +
           b.connection->name + "' (into " + res_.ports[b.port] + ")";
  }

  // What an unsat core of one message says: "passes the accept on line 34 of 'take' and makes
  // 'pull' emit a command that satisfies the resource's `when`".
  std::string core_text(const ResourceRule& a, const ResourceRule& b, const DataCore& core) const {
    std::vector<std::string> parts;
    for (size_t s = 0; s < 2; ++s) {
      const std::string& name = (s == 0 ? a : b).connection->name;
      if (!core.accept_lines[s].empty())
        parts.push_back("passes " + core_lines_text(core.accept_lines[s], name));
      if (core.predicate_used[s] && res_.uses)
        parts.push_back("makes '" + name + "' emit a command that satisfies the resource's `when`");
    }
    if (parts.empty()) return "makes both deliver a command that uses it";
    return join(parts, ", ", " and ");
  }

  void by_events(const ResourceRule& a, const ResourceRule& b) {
    out_.exclusive_by_events.push_back(
        pair_name(a, b) + ": `" + a.rule->effective_guard.to_string() + "` and `" +
        b.rule->effective_guard.to_string() + "` never hold together");
  }

  PortPair& port_pair(const ResourceRule& a, const ResourceRule& b);
  void check_pair(const ResourceRule& a, const ResourceRule& b);
  void refuted(const ResourceRule& a, const ResourceRule& b, bool same, const DataWitness& w,
               const std::vector<std::string>& state);
  bool replay(const ResourceRule& a, const ResourceRule& b, bool same, const DataWitness& w,
              MessageExample& ex, std::string* why);

  const model::App& app_;
  const std::vector<PortScope>& scopes_;
  const VerifyOptions& options_;
  z3::context& ctx_;
  Clock::time_point deadline_;
  DataQuery& data_;
  const model::Resource& res_;
  ResourceResult& out_;
  std::map<std::pair<size_t, size_t>, PortPair> port_pairs_;  // by the two ports' indices
};

// The pair of `a`'s and `b`'s ports (a.port < b.port), its overlapping pairs found on first use.
PortPair& ResourceChecker::port_pair(const ResourceRule& a, const ResourceRule& b) {
  auto [it, fresh] = port_pairs_.try_emplace({a.port, b.port});
  PortPair& pp = it->second;
  if (!fresh) return pp;
  pp.scope = joint_scope(*a.scope, *b.scope);
  pp.first_rules = static_cast<int>(a.scope->rules.size());
  pp.solver = std::make_unique<PortSolver>(pp.scope, ctx_, deadline_);
  const int n = pp.first_rules;
  std::vector<std::pair<int, int>> pairs;
  // Pairs within one port are the port's own check, not the resource's.
  Answer ans = pp.solver->overlapping_pairs(
      [n](int i, int j) { return (i < n) == (j < n) ? Known::No : Known::Unknown; }, pairs);
  pp.overlapping.insert(pairs.begin(), pairs.end());
  if (ans == Answer::Unknown) {
    pp.undecided = true;
    unknown("which rules of " + res_.ports[a.port] + " and " + res_.ports[b.port] +
                " can be selected together",
            pp.solver->unknown_reason());
  }
  return pp;
}

void ResourceChecker::check_pair(const ResourceRule& a, const ResourceRule& b) {
  ++out_.pairs;
  PortPair& pp = port_pair(a, b);
  const int ia = a.index, ib = pp.first_rules + b.index;
  if (!pp.undecided && !pp.overlapping.count({ia, ib})) {
    by_events(a, b);
    return;
  }
  for (const ResourceRule* r : {&a, &b}) {
    std::string why = data_.opaque_reason(*r->connection);
    if (why.empty()) continue;
    Finding f = base_finding(kCheckResource);
    f.rules = {a.connection->name, b.connection->name};
    f.rule_ports = {a.connection->destination, b.connection->destination};
    f.rule_locs = {a.connection->loc, b.connection->loc};
    f.message = "resource '" + res_.name + "' is not proved for " + pair_name(a, b) + ": '" +
                r->connection->name + "' is opaque for data (" + why + ")";
    f.notes.push_back({"without its body arbc must assume it can deliver any command", {}});
    out_.findings.push_back(std::move(f));
    return;
  }
  bool same = a.connection->source == b.connection->source;
  const model::BodyExpr* uses = res_.uses ? &*res_.uses : nullptr;
  DataWitness w;
  DataCore core;
  Answer ans = data_.ask({{a.connection, uses}, {b.connection, uses}}, &w, &core);
  if (ans == Answer::Unknown)
    return unknown("whether " + pair_name(a, b) + " can both use it", data_.unknown_reason());
  if (ans == Answer::Sat) {
    // The state is needed only now: a minimal one costs a query per event it drops.
    std::optional<std::vector<std::string>> state = pp.solver->minimal_state({ia, ib}, {});
    if (state) return refuted(a, b, same, w, *state);
    if (pp.solver->last_answer() == Answer::Unknown)
      return unknown("an event state that selects " + pair_name(a, b), pp.solver->unknown_reason());
    // Only when the overlapping pairs were undecided: the pair is exclusive by events after all.
    by_events(a, b);
    return;
  }
  std::string why = same ? "no " + a.connection->source + " message " + core_text(a, b, core)
                         : "one of them never delivers a command that uses it";
  out_.exclusive_by_data.push_back(pair_name(a, b) + (same ? " (one message)" : " (two messages)") +
                                   ": " + why);
  // One message of a source is one decision. Two of its messages before the event state changes
  // (a module reporting what the first command did) could give each rule one: not proved here.
  std::vector<std::string>& sources = out_.per_message_sources;
  if (same && std::find(sources.begin(), sources.end(), a.connection->source) == sources.end())
    sources.push_back(a.connection->source);
}

bool ResourceChecker::replay(const ResourceRule& a, const ResourceRule& b, bool same,
                             const DataWitness& w, MessageExample& ex, std::string* why) {
  if (!replay_accepts(options_.runner, {a.connection, b.connection}, w.messages, {0, same ? 0 : 1},
                      ex, why))
    return false;
  if (!res_.uses) return true;
  for (const ResourceRule* r : {&a, &b}) {
    const model::Port* p = app_.find_port(r->connection->destination);
    MonitorRun run;
    std::string err;
    options_.runner->run(*r->connection, w.messages[same || r == &a ? 0 : 1], &run, &err);
    std::optional<bool> uses = data_.holds(*res_.uses, run.delivered, *p->type);
    if (!uses || !*uses) {
      *why = "Z3 says '" + r->connection->name + "' delivers a command that uses '" + res_.name +
             "', but its Lua monitor delivers " + spec_value_text(run.delivered) +
             ", which does not";
      return false;
    }
  }
  return true;
}

void ResourceChecker::refuted(const ResourceRule& a, const ResourceRule& b, bool same,
                              const DataWitness& w, const std::vector<std::string>& state) {
  Finding f = base_finding(kCheckResource);
  f.rules = {a.connection->name, b.connection->name};
  f.rule_ports = {a.connection->destination, b.connection->destination};
  f.rule_locs = {a.connection->loc, b.connection->loc};
  f.message =
      pair_name(a, b) + " can both deliver a command that uses resource '" + res_.name + "' (" +
      (same ? "from one " + a.connection->source + " message" : "from two independent messages") +
      ")";
  f.notes.push_back({"in the event state (fewest events present): present: " +
                         (state.empty() ? std::string("none") : join(state)),
                     {}});
  for (size_t m = 0; m < w.messages.size(); ++m) {
    MessageExample ex;
    ex.source = w.message_sources[m];
    ex.value = spec_value_text(w.messages[m]);
    f.messages.push_back(ex);
    f.notes.push_back(
        {std::string(same ? "the message: " : "message " + std::to_string(m + 1) + ": ") +
             ex.source + " = " + ex.value,
         {}});
  }
  for (size_t s = 0; s < 2; ++s) {
    const ResourceRule& r = s == 0 ? a : b;
    f.notes.push_back({"'" + r.connection->name + "' is selected (`" +
                           r.rule->effective_guard.to_string() + "`) and delivers " +
                           spec_value_text(w.emitted[s]) + " to " + res_.ports[r.port],
                       r.connection->loc});
  }
  std::vector<std::string> assumed = w.assumed_state[0];
  assumed.insert(assumed.end(), w.assumed_state[1].begin(), w.assumed_state[1].end());
  if (!assumed.empty()) {
    f.notes.push_back({"with monitor state " + join(assumed) +
                           " (abstracted: any value earlier messages could leave), so not "
                           "replayed",
                       {}});
  } else if (options_.runner) {
    MessageExample ex;
    std::string why;
    if (!replay(a, b, same, w, ex, &why)) {
      out_.findings.push_back(internal_data_error("", res_.loc, why));
      return;
    }
    f.messages.back().replay = ex.replay;
    f.notes.push_back({"replayed through the Lua monitors: " + join(ex.replay, "; "), {}});
  } else {
    f.notes.push_back({"not replayed (no monitor runner)", {}});
  }
  f.notes.push_back(
      {"make the rules' bodies exclusive on the message (an `accept` or an `if` "
       "on the same field), or their `when`s exclusive through an event both "
       "ports read",
       {}});
  out_.findings.push_back(std::move(f));
}

}  // namespace

void run_resource_checks(const model::App& app, const std::vector<PortScope>& scopes,
                         const VerifyOptions& options, z3::context& ctx, Clock::time_point deadline,
                         DataQuery& data, VerifyReport& report) {
  for (const model::Resource& res : app.resources) {
    ResourceResult out;
    ResourceChecker(app, scopes, options, ctx, deadline, data, res, out).run();
    report.resources.push_back(std::move(out));
  }
}

}  // namespace arbc::verify
