// to_app_json: the core model as app.json text (docs/app-json.md), written in one pass with
// JsonWriter. Reading it back is app_json.cc's job.
#include "runtime/app_json.h"
#include "runtime/json_writer.h"

namespace arbc::model {

namespace {

const char* op_name(Constraint::Op op) {
  switch (op) {
    case Constraint::Op::True:
      return "true";
    case Constraint::Op::False:
      return "false";
    case Constraint::Op::Event:
      return "event";
    case Constraint::Op::Not:
      return "not";
    case Constraint::Op::And:
      return "and";
    case Constraint::Op::Or:
      return "or";
  }
  return "?";
}

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

void write_location(JsonWriter& w, const SourceLocation& loc) {
  w.key("loc");
  w.begin_object();
  w.key("file");
  w.value(loc.file);
  w.key("line");
  w.value(loc.line);
  w.key("column");
  w.value(loc.column);
  w.key("end_line");
  w.value(loc.end_line);
  w.key("end_column");
  w.value(loc.end_column);
  w.end_object();
}

void write_tree(JsonWriter& w, const Constraint& c) {
  w.begin_object();
  w.key("op");
  w.value(op_name(c.op));
  if (c.op == Constraint::Op::Event) {
    w.key("event");
    w.value(c.event);
  }
  if (!c.args.empty()) {
    w.key("args");
    w.begin_array();
    for (const Constraint& a : c.args) write_tree(w, a);
    w.end_array();
  }
  w.end_object();
}

// A constraint both as text (for people) and as a tree (for tools that do not parse the text).
void write_constraint(JsonWriter& w, const char* key, const Constraint& c) {
  w.key(key);
  w.begin_object();
  w.key("text");
  w.value(c.to_string());
  w.key("tree");
  write_tree(w, c);
  w.end_object();
}

void write_optional(JsonWriter& w, const char* key, const std::optional<double>& v) {
  w.key(key);
  if (v) {
    w.value(*v);
  } else {
    w.null();
  }
}

void write_module(JsonWriter& w, const Module& m) {
  w.begin_object();
  w.key("name");
  w.value(m.name);
  w.key("doc");
  w.value(m.doc);
  w.key("ports");
  w.begin_array();
  for (const Port& p : m.ports) {
    w.begin_object();
    w.key("name");
    w.value(p.name);
    w.key("direction");
    w.value(p.direction == Direction::In ? "in" : "out");
    w.key("type");
    w.value(p.type ? p.type->to_string() : "");
    write_location(w, p.loc);
    w.end_object();
  }
  w.end_array();
  write_location(w, m.loc);
  w.end_object();
}

void write_connection(JsonWriter& w, const Connection& c) {
  w.begin_object();
  w.key("name");
  w.value(c.name);
  w.key("source");
  w.value(c.source);
  w.key("destination");
  w.value(c.destination);
  w.key("kind");
  w.value(kind_name(c.kind));
  w.key("generated");
  w.value(c.generated);
  write_constraint(w, "constraint", c.constraint);
  w.key("sets");
  w.value(c.sets);
  w.key("unsets");
  w.value(c.unsets);
  w.key("must_set");
  w.value(c.must_set);
  w.key("must_unset");
  w.value(c.must_unset);
  w.key("opaque");
  w.value(c.opaque);
  write_optional(w, "trig_interval", c.trig_interval);
  write_optional(w, "throttle", c.throttle);
  w.key("monitor");
  w.value(c.monitor);
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
  w.key("port");
  w.value(a.port);
  w.key("by_priority");
  w.value(a.by_priority);
  w.key("complete");
  w.value(a.complete);
  w.key("rules");
  w.value(a.rules);
  w.key("asserts");
  w.begin_array();
  for (const Assertion& as : a.asserts) {
    w.begin_object();
    w.key("rule");
    w.value(as.rule);
    write_constraint(w, "property", as.property);
    write_location(w, as.loc);
    w.end_object();
  }
  w.end_array();
  write_location(w, a.loc);
  w.end_object();
}

}  // namespace

std::string to_app_json(const App& app) {
  JsonWriter w;
  w.begin_object();
  w.key("schema_version");
  w.value(app.schema_version);
  w.key("name");
  w.value(app.name);
  w.key("description");
  w.value(app.description);
  w.key("spec_file");
  w.value(app.spec_file);
  w.key("modules");
  w.begin_array();
  for (const Module& m : app.modules) write_module(w, m);
  w.end_array();
  w.key("events");
  w.begin_array();
  for (const Event& e : app.events) {
    w.begin_object();
    w.key("name");
    w.value(e.name);
    write_optional(w, "lifetime", e.lifetime);
    w.key("source");
    w.value(e.source);
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
    w.key("events");
    w.value(g.events);
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
  w.end_object();
  return w.take() + "\n";
}

}  // namespace arbc::model
