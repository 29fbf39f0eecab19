#include "compiler/lower/lower.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "compiler/lower/event_effects.h"
#include "compiler/lower/feeds.h"
#include "compiler/lower/lower_body.h"
#include "compiler/lower/temporal.h"
#include "compiler/lower/test_cases.h"
#include "compiler/lower/test_containers.h"
#include "core/check_ids.h"
#include "core/effective_guard.h"

namespace arbc::lower {

namespace {

Diagnostic error_at(const model::SourceLocation& loc, std::string message, DiagId id) {
  Diagnostic d;
  d.severity = Severity::Error;
  d.loc = loc;
  d.message = std::move(message);
  d.id = id.text();
  return d;
}

std::vector<std::string> sorted(const std::set<std::string>& s) { return {s.begin(), s.end()}; }

// `a and b and ...` without `true` parts (a rule without `when` is `true`); `true` if empty.
Constraint all_of(std::vector<Constraint> parts) {
  std::vector<Constraint> kept;
  for (Constraint& p : parts)
    if (p.op != Constraint::Op::True) kept.push_back(std::move(p));
  if (kept.empty()) return Constraint::constant(true);
  if (kept.size() == 1) return std::move(kept[0]);
  return Constraint::conjunction(std::move(kept));
}

// Visits every statement of a block, nested ones included.
template <typename F>
void for_each_stmt(const ast::Block& block, F&& f) {
  for (const auto& s : block) {
    f(*s);
    for_each_stmt(s->body, f);
    for_each_stmt(s->else_body, f);
  }
}

// A rule of one arbitrated port while it is being lowered.
struct RuleWork {
  const ast::Rule* rule = nullptr;
  size_t connection = 0;
  std::string activity;  // activity event; empty outside `by priority` and for the lowest rule
  EventEffects effects;
  bool opaque = false;
};

class Lowerer {
 public:
  Lowerer(const ast::Spec& spec, const LowerOptions& options, LoweredApp& out,
          std::vector<Diagnostic>& diagnostics)
      : spec_(spec), options_(options), out_(out), diagnostics_(diagnostics) {}

  void run() {
    model::App& app = out_.app;
    app.spec_file = spec_.file;
    if (spec_.app) {
      app.name = spec_.app->name;
      app.description = spec_.app->doc;
    } else {  // no `app` declaration: the spec file's name, as in specs/<app>.spec
      app.name = std::filesystem::path(spec_.file).stem().string();
    }
    lower_modules();
    lower_events();
    for (const ast::ArbitrateDecl& a : spec_.arbitrations) lower_arbitration(a);
    for (const ast::ConnectDecl& c : spec_.connects) lower_connect(c);
    for (const ast::ExclusiveDecl& x : spec_.exclusives) {
      model::ExclusiveGroup g;
      for (const ast::EventName& e : x.events) g.events.push_back(e.name);
      g.loc = x.loc;
      app.exclusive_groups.push_back(std::move(g));
    }
    for (const ast::InvariantDecl& inv : spec_.invariants)
      app.invariants.push_back({inv.constraint, inv.loc});
    for (const ast::TemporalDecl& n : spec_.temporal)
      if (auto t = lower_temporal(n)) app.temporal.push_back(std::move(*t));
    for (const ast::AssumeDecl& a : spec_.assumptions) {
      if (!a.after_decl) continue;  // sema reported it
      std::optional<Nanos> absent_for;
      if (a.absent_for.expr) absent_for = a.absent_for.nanos;
      app.assumptions.push_back(
          {a.event, a.after_decl->port->port.qualified(), a.after, a.until, a.loc, absent_for});
    }
    for (const ast::RateDecl& r : spec_.rates)
      if (r.port.port_decl) app.rates.push_back({r.port.qualified(), r.period.nanos, r.loc});
    for (const ast::ResourceDecl& r : spec_.resources) {
      model::Resource res;
      res.name = r.name;
      for (const ast::PortRef& p : r.ports) res.ports.push_back(p.qualified());
      if (r.uses && !r.ports.empty())
        res.uses = lower_expr(*r.uses, port_type(r.ports.front().qualified()));
      res.loc = r.loc;
      app.resources.push_back(std::move(res));
    }
  }

 private:
  void lower_modules() {
    for (const ast::TypeDecl& t : spec_.types)
      out_.app.types.push_back({t.name, t.type.resolved, t.loc, t.ros2});
    for (const ast::ModuleDecl& m : spec_.modules) {
      model::Module mm;
      mm.name = m.name;
      mm.doc = m.doc;
      mm.loc = m.loc;
      for (const ast::PortDecl& p : m.ports)
        mm.ports.push_back({p.name, p.direction, p.type.resolved, p.loc});
      out_.app.modules.push_back(std::move(mm));
    }
  }

  void lower_events() {
    for (const ast::EventSymbol& e : spec_.event_symbols) {
      model::Event event{e.name, e.lifetime, e.source, e.loc, std::nullopt};
      if (e.kind == ast::EventSymbol::Kind::Status) event.flag = e.flag.empty() ? e.name : e.flag;
      event.fail_open_after = e.fail_open_after;
      for (const ast::DerivedEventDecl& d : spec_.derived_events)
        if (d.name == e.name && d.predicate)
          event.predicate = lower_expr(*d.predicate, port_type(d.source.qualified()));
      out_.app.events.push_back(std::move(event));
    }
  }

  // The type of port "Module.port" (modules are lowered first); null if there is none.
  TypePtr port_type(const std::string& port) const {
    const model::Port* p = out_.app.find_port(port);
    return p ? p->type : nullptr;
  }

  size_t add_connection(model::Connection c, MonitorPlan plan) {
    plan.connection = out_.app.connections.size();
    out_.app.connections.push_back(std::move(c));
    out_.monitors.push_back(std::move(plan));
    return plan.connection;
  }

  // Reads a `script "file.lua"` statement's file; reports and returns nullopt on failure.
  std::optional<ScriptSource> read_script(const ast::Stmt& s) {
    std::filesystem::path path(s.text);
    if (path.is_relative()) path = std::filesystem::path(options_.script_dir) / path;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      diagnostics_.push_back(error_at(s.loc,
                                      "cannot read script '" + s.text + "' (looked for '" +
                                          path.lexically_normal().string() +
                                          "'); script paths are relative to the spec's directory",
                                      diag::Script));
      return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    ScriptSource script{path.lexically_normal().string(), text.str(), s.loc};
    return script;  // Sema has checked that it compiles (frontend/lua_syntax.h)
  }

  // Fills throttle, trig interval and the script of a rule or connect body; false on error.
  // Sema has checked the body's shape: at most one `throttle` and one `every`, both at the
  // top level, and a `script` alone in its body.
  bool lower_body_options(const ast::Block& body, model::Connection& c, MonitorPlan& plan) {
    const ast::Stmt* script = nullptr;
    for_each_stmt(body, [&](const ast::Stmt& s) {
      if (s.kind == ast::Stmt::Kind::Throttle && !c.throttle && s.duration)
        c.throttle = s.duration->nanos;
      if (s.kind == ast::Stmt::Kind::Every && s.duration) c.trig_interval = s.duration->nanos;
      if (s.kind == ast::Stmt::Kind::Script) script = &s;
    });
    if (script) {
      plan.script = read_script(*script);
      if (!plan.script) return false;
      c.opaque = true;
      return true;
    }
    c.body = lower_body(body, port_type(c.source), port_type(c.destination));
    return true;
  }

  void lower_arbitration(const ast::ArbitrateDecl& a) {
    const std::string port = a.port.qualified();
    model::ArbitratedPort ap;
    ap.port = port;
    ap.by_priority = a.by_priority;
    ap.complete = a.complete;
    ap.loc = a.loc;

    std::vector<RuleWork> rules;
    for (size_t k = 0; k < a.rules.size(); ++k) {
      const ast::Rule& r = a.rules[k];
      RuleWork w;
      w.rule = &r;
      bool lowest = k + 1 == a.rules.size();
      if (a.by_priority && !lowest) {
        w.activity = activity_event_name(r.name);
      }
      model::Connection c;
      c.name = r.name;
      c.source = r.source.qualified();
      c.destination = port;
      c.kind = model::ConnectionKind::Rule;
      c.loc = r.loc;
      c.monitor = monitor_path(port, r.name);
      MonitorPlan plan;
      plan.kind = MonitorPlan::Kind::Rule;
      plan.message_name = r.message_name.empty() ? r.source.port : r.message_name;
      lower_body_options(r.body, c, plan);
      if (plan.script) {
        w.effects = script_effects(plan.script->text);
        w.opaque = true;
      } else {
        w.effects = body_effects(r.body);
      }
      // The runtime sets the activity event each time the rule delivers (after the decision,
      // so not a must-set); the connection owns its entries, so it is among its `sets`.
      if (!w.activity.empty()) w.effects.sets.insert(w.activity);
      c.activity_event = w.activity;
      // `then set e` / `then unset e`: done by the runtime as the rule delivers, like the
      // activity event; the entries it sets are the connection's own.
      for (const ast::DeliveryEffect& x : r.on_delivery) {
        (x.set ? c.delivery_sets : c.delivery_unsets).push_back(x.event);
        if (x.set) w.effects.sets.insert(x.event);
      }
      w.connection = add_connection(std::move(c), std::move(plan));
      ap.rules.push_back(r.name);
      if (!w.activity.empty()) {
        std::optional<Nanos> hold;
        if (r.hold) hold = r.hold->nanos;
        out_.app.events.push_back({w.activity, hold, "", r.loc});
      }
      rules.push_back(std::move(w));
    }
    lower_constraints(rules, ap);
    lower_feeds(rules, ap);
    out_.app.arbitrated_ports.push_back(std::move(ap));
  }

  // The selection constraint of each rule (`otherwise` last: it needs the others' effective
  // guards), the port's assertions, and each rule's event effects.
  void lower_constraints(std::vector<RuleWork>& rules, model::ArbitratedPort& ap) {
    const std::string& port = ap.port;
    // Constraints of the rules that are not `otherwise`.
    for (size_t k = 0; k < rules.size(); ++k) {
      if (rules[k].rule->otherwise) continue;
      connection(rules[k]).constraint = priority_constraint(rules, k, rules[k].rule->constraint);
    }
    for (const ast::AssertDecl& as : spec_.asserts)
      if (as.port.qualified() == port) ap.asserts.push_back(lower_assert(as, port_type(port)));

    // The effects first: `otherwise` reads them through the other rules' effective guards.
    for (RuleWork& w : rules) {
      model::Connection& c = connection(w);
      c.sets = sorted(w.effects.sets);
      c.unsets = sorted(w.effects.unsets);
      c.must_set = sorted(w.effects.must_set);
      c.must_unset = sorted(w.effects.must_unset);
      c.opaque = w.opaque;
    }
    for (size_t k = 0; k < rules.size(); ++k) {
      if (!rules[k].rule->otherwise) continue;
      Constraint none = otherwise_constraint(rules, k);
      connection(rules[k]).constraint = priority_constraint(rules, k, none);
    }
  }

  // A generated feed connection per source of the stream events the port's constraints and
  // assertions read.
  void lower_feeds(const std::vector<RuleWork>& rules, const model::ArbitratedPort& ap) {
    const std::string& port = ap.port;
    std::set<std::string> read = events_read(rules, ap);
    std::set<std::string> taken_names(ap.rules.begin(), ap.rules.end());
    for (FeedGroup& g : plan_feeds(spec_, read)) {
      model::Connection c;
      c.name = unique_name(feed_name(g.source), taken_names);
      c.source = g.source;
      c.destination = port;
      c.kind = model::ConnectionKind::Feed;
      c.generated = true;
      c.constraint = Constraint::constant(false);
      c.sets = g.sets;
      c.unsets = g.unsets;
      c.loc = g.loc;
      c.monitor = monitor_path(port, c.name);
      g.plan.kind = MonitorPlan::Kind::Feed;
      add_connection(std::move(c), std::move(g.plan));
    }
  }

  model::Connection& connection(const RuleWork& w) { return out_.app.connections[w.connection]; }

  // `when_k and not act_1 ... and not act_(k-1)` (docs/design.md#priorities-and-holds): rule k
  // is suppressed while a higher rule delivered within its hold; just `when_k` outside
  // `by priority`. Rule k's own act_k is set as it delivers, so its constraint cannot read it.
  Constraint priority_constraint(const std::vector<RuleWork>& rules, size_t k, Constraint when) {
    std::vector<Constraint> parts{std::move(when)};
    for (size_t j = 0; j < k; ++j)
      if (!rules[j].activity.empty())
        parts.push_back(Constraint::negate(Constraint::event_ref(rules[j].activity)));
    return all_of(std::move(parts));
  }

  // `otherwise`: none of the other rules' effective guards (core/effective_guard.h) holds. The
  // feeds are not there yet; they set only stream events, which no monitor code unsets, so the
  // guards are the same without them.
  Constraint otherwise_constraint(const std::vector<RuleWork>& rules, size_t k) {
    std::vector<const model::Connection*> into;
    for (const RuleWork& w : rules) into.push_back(&connection(w));
    std::vector<Constraint> others;
    for (size_t j = 0; j < rules.size(); ++j)
      if (j != k && !rules[j].rule->otherwise)
        others.push_back(model::effective_guard(into, *into[j]));
    if (others.empty()) return Constraint::constant(true);
    return Constraint::negate(Constraint::disjunction(std::move(others)));
  }

  // The events the port's rule constraints and assertions read.
  std::set<std::string> events_read(const std::vector<RuleWork>& rules,
                                    const model::ArbitratedPort& ap) {
    std::set<std::string> read;
    for (const RuleWork& w : rules) connection(w).constraint.collect_events(read);
    for (const model::Assertion& as : ap.asserts) as.property.collect_events(read);
    // `never RULE while EVENT` reads EVENT in RULE's port, so its feed is generated as for a
    // constraint (docs/design.md#feeds).
    for (const ast::TemporalDecl& t : spec_.temporal) {
      const ast::ArbitrateDecl* port = t.rule_decl ? t.rule_decl->port : t.port_decl;
      if (!port || port->port.qualified() != ap.port) continue;
      if (t.kind == ast::TemporalDecl::Kind::Absence) read.insert(t.event);
      // A response's `while` and its trigger event are read in the same port.
      if (t.kind == ast::TemporalDecl::Kind::Response) {
        t.condition_sema.collect_events(read);
        if (!t.event.empty()) read.insert(t.event);
      }
    }
    return read;
  }

  static std::string feed_name(const std::string& source) {
    std::string name = "feed_" + source;
    for (char& ch : name)
      if (ch == '.') ch = '_';
    return name;
  }

  static std::string unique_name(const std::string& base, std::set<std::string>& taken) {
    std::string name = base;
    for (int i = 2; taken.count(name); ++i) name = base + "_" + std::to_string(i);
    taken.insert(name);
    return name;
  }

  void lower_connect(const ast::ConnectDecl& d) {
    model::Connection c;
    c.name = feed_name(d.source.qualified()).replace(0, 5, "from_");
    c.source = d.source.qualified();
    c.destination = d.destination.qualified();
    c.kind = model::ConnectionKind::Connect;
    c.constraint = Constraint::constant(true);
    c.loc = d.loc;
    c.monitor = monitor_path(c.destination, c.name);
    MonitorPlan plan;
    plan.kind = MonitorPlan::Kind::Connect;
    plan.message_name = d.message_name.empty() ? d.source.port : d.message_name;
    lower_body_options(d.body, c, plan);
    EventEffects effects = plan.script ? script_effects(plan.script->text) : body_effects(d.body);
    c.sets = sorted(effects.sets);
    c.unsets = sorted(effects.unsets);
    c.must_set = sorted(effects.must_set);
    c.must_unset = sorted(effects.must_unset);
    add_connection(std::move(c), std::move(plan));
  }

  const ast::Spec& spec_;
  const LowerOptions& options_;
  LoweredApp& out_;
  std::vector<Diagnostic>& diagnostics_;
};

}  // namespace

std::string monitor_path(const std::string& port, const std::string& name) {
  return "monitors/" + port + "__" + name + ".lua";
}

std::string activity_event_name(const std::string& rule) { return ast::activity_event_name(rule); }

LowerResult lower_spec(std::shared_ptr<const ast::Spec> spec, const LowerOptions& options) {
  LowerResult result;
  auto lowered = std::make_shared<LoweredApp>();
  Lowerer(*spec, options, *lowered, result.diagnostics).run();
  lowered->tests = lower_tests(*spec);
  resolve_test_containers(lowered->app, lowered->tests, result.diagnostics);
  result.ok = true;
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == Severity::Error) result.ok = false;
  if (result.ok) result.lowered = std::move(lowered);
  return result;
}

}  // namespace arbc::lower
