#include "verify/resource_checks.h"

#include <algorithm>
#include <memory>
#include <optional>

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
};

// The two rules' effective guards over one event state: the union of both ports' scopes and
// domains (an event name is one fact for the resource, docs/checks.md#resource).
PortScope joint_scope(const ResourceRule& a, const ResourceRule& b) {
  PortScope j;
  j.port = a.scope->port;
  j.rules = {*a.rule, *b.rule};
  j.events = a.scope->events;
  j.events.insert(j.events.end(), b.scope->events.begin(), b.scope->events.end());
  std::sort(j.events.begin(), j.events.end());
  j.events.erase(std::unique(j.events.begin(), j.events.end()), j.events.end());
  j.domain = a.scope->domain;
  for (const DomainConstraint& d : b.scope->domain) {
    bool known = false;
    for (const DomainConstraint& e : j.domain) known |= e.text == d.text;
    if (!known) j.domain.push_back(d);
  }
  return j;
}

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

 private:
  // The rules into the resource's ports.
  std::vector<ResourceRule> resource_rules() {
    std::vector<ResourceRule> out;
    for (size_t p = 0; p < res_.ports.size(); ++p) {
      for (const PortScope& s : scopes_) {
        if (s.port->port != res_.ports[p]) continue;
        for (const ScopedRule& r : s.rules) out.push_back({r.connection, p, &s, &r});
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
};

void ResourceChecker::check_pair(const ResourceRule& a, const ResourceRule& b) {
  ++out_.pairs;
  PortScope joint = joint_scope(a, b);
  PortSolver solver(joint, ctx_, deadline_);
  std::optional<std::vector<std::string>> state = solver.minimal_state({0, 1}, {});
  if (!state) {
    if (solver.last_answer() == Answer::Unknown)
      return unknown("whether " + pair_name(a, b) + " can be selected together",
                     solver.unknown_reason());
    out_.proved.push_back(pair_name(a, b) + ": exclusive by events: `" +
                          a.rule->effective_guard.to_string() + "` and `" +
                          b.rule->effective_guard.to_string() + "` never hold together");
    return;
  }
  for (const ResourceRule* r : {&a, &b}) {
    std::string why = data_.opaque_reason(*r->connection);
    if (why.empty()) continue;
    Finding f = base_finding(kCheckResource);
    f.rules = {a.connection->name, b.connection->name};
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
  if (ans == Answer::Sat) return refuted(a, b, same, w, *state);
  std::string why = same ? "no " + a.connection->source + " message passes both " +
                               core_lines_text(core.accept_lines[0], a.connection->name) + " and " +
                               core_lines_text(core.accept_lines[1], b.connection->name)
                         : "one of them never delivers a command that uses it";
  std::vector<std::string> by_when;
  for (size_t s = 0; s < 2; ++s)
    if (core.predicate_used[s]) by_when.push_back("'" + (s == 0 ? a : b).connection->name + "'");
  if (!by_when.empty() && res_.uses)
    why += " with what " + join(by_when, ", ", " and ") + " then emit" +
           (by_when.size() == 1 ? "s" : "") + " satisfying the resource's `when`";
  out_.proved.push_back(pair_name(a, b) + (same ? " (one message)" : " (two messages)") + ": " +
                        why);
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
