// to_app_json: the core model as app.json text (docs/app-json.md), written in one pass with
// JsonWriter. Reading it back is app_json.cc's job.
#include "core/app_json.h"
#include "core/artifact_path.h"
#include "core/body_text.h"
#include "core/json_text.h"
#include "core/json_writer.h"

namespace arbc::model {

namespace {

const char* kind_name(ConnectionKind k) {
  switch (k) {
    case ConnectionKind::Rule:
      return "rule";
    case ConnectionKind::Feed:
      return "feed";
    case ConnectionKind::Connect:
      return "connect";
  }
  return "?";
}

// The paths of the app.json being written, as an artifact names them (core/artifact_path.h):
// set by to_app_json for the duration of one call, so that the many writers of a location
// need no extra parameter.
thread_local ArtifactPaths* t_paths = nullptr;

void write_location(JsonWriter& w, const SourceLocation& loc) {
  w.key("loc");
  w.begin_object();
  w.member("file", (*t_paths)(loc.file));
  w.member("line", loc.line);
  w.member("column", loc.column);
  w.member("end_line", loc.end_line);
  w.member("end_column", loc.end_column);
  w.end_object();
}

// A constraint is its text (core/constraint.h): the one representation in app.json.
void write_constraint(JsonWriter& w, const char* key, const Constraint& c) {
  w.member(key, c.to_string());
}

// A duration as the exact decimal of its seconds: app.json never holds a rounded one.
void write_seconds(JsonWriter& w, const char* key, Nanos d) {
  w.key(key);
  std::string text;
  append_json_seconds(text, d);
  w.number_text(text);
}

void write_optional(JsonWriter& w, const char* key, const std::optional<Nanos>& v) {
  if (v) {
    write_seconds(w, key, *v);
  } else {
    w.key(key);
    w.null();
  }
}

void write_module(JsonWriter& w, const Module& m) {
  w.begin_object();
  w.member("name", m.name);
  w.member("doc", m.doc);
  w.key("ports");
  w.begin_array();
  for (const Port& p : m.ports) {
    w.begin_object();
    w.member("name", p.name);
    w.member("direction", p.direction == Direction::In ? "in" : "out");
    w.member("type", p.type ? p.type->to_string() : "");
    write_location(w, p.loc);
    w.end_object();
  }
  w.end_array();
  write_location(w, m.loc);
  w.end_object();
}

void write_connection(JsonWriter& w, const Connection& c) {
  w.begin_object();
  w.member("name", c.name);
  w.member("source", c.source);
  w.member("destination", c.destination);
  w.member("kind", kind_name(c.kind));
  w.member("generated", c.generated);
  write_constraint(w, "constraint", c.constraint);
  w.member("sets", c.sets);
  w.member("unsets", c.unsets);
  w.member("must_set", c.must_set);
  w.member("must_unset", c.must_unset);
  w.member("activity_event", c.activity_event);
  if (!c.delivery_sets.empty()) w.member("delivery_sets", c.delivery_sets);
  if (!c.delivery_unsets.empty()) w.member("delivery_unsets", c.delivery_unsets);
  w.member("opaque", c.opaque);
  if (c.body) {
    w.key("body");
    w.begin_array();
    for (const BodyStmt& s : *c.body) w.value(body_stmt_text(s));
    w.end_array();
  }
  write_optional(w, "trig_interval", c.trig_interval);
  write_optional(w, "throttle", c.throttle);
  if (c.list_bound > 0) w.member("list_bound", c.list_bound);  // absent: any length
  w.member("monitor", c.monitor);
  w.member("monitor_sha256", c.monitor_sha256);
  w.key("source_map");
  w.begin_array();
  for (const SourceMapEntry& e : c.source_map) {
    w.begin_array();
    w.value(e.monitor_line);
    w.value(e.spec_line);
    w.end_array();
  }
  w.end_array();
  write_location(w, c.loc);
  w.end_object();
}

void write_arbitrated_port(JsonWriter& w, const ArbitratedPort& a) {
  w.begin_object();
  w.member("port", a.port);
  w.member("by_priority", a.by_priority);
  w.member("complete", a.complete);
  w.member("rules", a.rules);
  w.key("asserts");
  w.begin_array();
  for (const Assertion& as : a.asserts) {
    w.begin_object();
    w.member("rule", as.rule);
    write_constraint(w, "property", as.property);
    if (as.emitted) w.member("emitted", body_expr_text(*as.emitted));
    write_location(w, as.loc);
    w.end_object();
  }
  w.end_array();
  write_location(w, a.loc);
  w.end_object();
}

// The `resources` section.
void write_resources(JsonWriter& w, const std::vector<Resource>& resources) {
  if (!resources.empty()) {  // absent when none: apps without resources keep their bytes
    w.key("resources");
    w.begin_array();
    for (const Resource& r : resources) {
      w.begin_object();
      w.member("name", r.name);
      w.member("ports", r.ports);
      if (r.uses) w.member("uses", body_expr_text(*r.uses));
      write_location(w, r.loc);
      w.end_object();
    }
    w.end_array();
  }
}

// The `rates` section (`given M.p every D;`), written only when there are some.
void write_rates(JsonWriter& w, const std::vector<SourceRate>& rates) {
  if (rates.empty()) return;
  w.key("rates");
  w.begin_array();
  for (const SourceRate& r : rates) {
    w.begin_object();
    w.member("port", r.port);
    write_seconds(w, "every", r.period);
    write_location(w, r.loc);
    w.end_object();
  }
  w.end_array();
}

// The `temporal` section (properties over time).
void write_temporal(JsonWriter& w, const std::vector<TemporalProperty>& temporal) {
  // Written only when there are some: every app.json written before properties over time
  // existed reads the same, and its bytes (and digests in goldens) do not change.
  if (!temporal.empty()) {
    w.key("temporal");
    w.begin_array();
    for (const TemporalProperty& t : temporal) {
      w.begin_object();
      w.member("kind", temporal_kind_name(t.kind));
      w.member("port", t.port);
      if (!t.rule.empty()) w.member("rule", t.rule);
      if (t.kind == TemporalProperty::Kind::Spacing || t.kind == TemporalProperty::Kind::Stability)
        write_seconds(w, "window", t.window);
      // Written only when there is one: a spacing of one rule reads as it did before `after`.
      if (t.kind == TemporalProperty::Kind::Spacing && !t.other.empty()) w.member("after", t.other);
      if (t.kind == TemporalProperty::Kind::Absence) w.member("event", t.event);
      if (t.kind == TemporalProperty::Kind::Precedence) w.member("after", t.other);
      if (t.kind == TemporalProperty::Kind::Response) {
        if (t.event.empty()) w.member("after", t.other);
        if (!t.event.empty()) w.member("event", t.event);
        w.member("stops", t.stops);
        write_seconds(w, "window", t.window);
        write_constraint(w, "while", t.condition);
      }
      write_location(w, t.loc);
      w.end_object();
    }
    w.end_array();
  }
}

// The `assumptions` section (environment assumptions), written only when there are some.
void write_assumptions(JsonWriter& w, const std::vector<Assumption>& assumptions) {
  if (assumptions.empty()) return;
  w.key("assumptions");
  w.begin_array();
  for (const Assumption& a : assumptions) {
    w.begin_object();
    w.member("event", a.event);
    w.member("port", a.port);
    w.member("after", a.after);
    if (!a.until.empty()) w.member("until", a.until);
    if (a.absent_for) write_seconds(w, "absent_for", *a.absent_for);
    write_location(w, a.loc);
    w.end_object();
  }
  w.end_array();
}

}  // namespace

std::string to_app_json(const App& app) {
  ArtifactPaths paths;
  t_paths = &paths;
  JsonWriter w;
  w.begin_object();
  w.member("schema_version", app.schema_version);
  w.member("name", app.name);
  w.member("description", app.description);
  w.member("spec_file", paths(app.spec_file));
  if (!app.claims_script.empty()) {  // absent: no claim over delivered values
    w.member("claims_script", app.claims_script);
    w.member("claims_script_sha256", app.claims_script_sha256);
  }
  w.key("types");
  w.begin_array();
  for (const NamedType& t : app.types) {
    w.begin_object();
    w.member("name", t.name);
    w.member("type", t.type ? t.type->to_string() : "");
    if (!t.ros2.empty()) w.member("ros2", t.ros2);
    write_location(w, t.loc);
    w.end_object();
  }
  w.end_array();
  w.key("modules");
  w.begin_array();
  for (const Module& m : app.modules) write_module(w, m);
  w.end_array();
  w.key("events");
  w.begin_array();
  for (const Event& e : app.events) {
    w.begin_object();
    w.member("name", e.name);
    write_optional(w, "lifetime", e.lifetime);
    w.member("source", e.source);
    if (e.predicate) w.member("predicate", body_expr_text(*e.predicate));
    if (!e.flag.empty()) w.member("flag", e.flag);
    if (e.fail_open_after) write_optional(w, "fail_open_after", e.fail_open_after);
    write_location(w, e.loc);
    w.end_object();
  }
  w.end_array();
  w.key("connections");
  w.begin_array();
  for (const Connection& c : app.connections) write_connection(w, c);
  w.end_array();
  w.key("arbitrated_ports");
  w.begin_array();
  for (const ArbitratedPort& a : app.arbitrated_ports) write_arbitrated_port(w, a);
  w.end_array();
  w.key("exclusive_groups");
  w.begin_array();
  for (const ExclusiveGroup& g : app.exclusive_groups) {
    w.begin_object();
    w.member("events", g.events);
    write_location(w, g.loc);
    w.end_object();
  }
  w.end_array();
  w.key("invariants");
  w.begin_array();
  for (const Invariant& inv : app.invariants) {
    w.begin_object();
    write_constraint(w, "formula", inv.formula);
    write_location(w, inv.loc);
    w.end_object();
  }
  w.end_array();
  write_resources(w, app.resources);
  write_temporal(w, app.temporal);
  write_assumptions(w, app.assumptions);
  write_rates(w, app.rates);
  w.end_object();
  t_paths = nullptr;
  return w.take() + "\n";
}

}  // namespace arbc::model
