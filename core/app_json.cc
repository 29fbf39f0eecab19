#include "core/app_json.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "core/body_text.h"
#include "core/body_types.h"
#include "core/check_ids.h"
#include "core/decimal_text.h"
#include "core/instant.h"
#include "core/json_diagnostic.h"

namespace arbc::model {

using Json = nlohmann::ordered_json;

namespace {

// Reading (docs/design.md#reporting-errors): each helper returns false (or nullptr) and sets
// *err to the JSON path of the offending value and what is wrong. nlohmann-json is asked for a
// value only after its type was checked, so it throws only on a bug (caught in from_app_json).

bool fail(std::string message, std::string* err) {
  *err = std::move(message);
  return false;
}

const Json* member(const Json& j, const std::string& path, const char* key, std::string* err) {
  if (!j.is_object()) {
    *err = path + ": expected an object";
    return nullptr;
  }
  auto it = j.find(key);
  if (it == j.end()) {
    *err = path + ": missing \"" + key + "\"";
    return nullptr;
  }
  return &*it;
}

bool get_string(const Json& j, const std::string& path, const char* key, std::string* out,
                std::string* err) {
  const Json* v = member(j, path, key, err);
  if (!v) return false;
  if (!v->is_string()) return fail(path + "." + key + ": expected a string", err);
  *out = v->get<std::string>();
  return true;
}

bool opt_string(const Json& j, const std::string& path, const char* key, std::string* out,
                std::string* err) {
  return !j.contains(key) || get_string(j, path, key, out, err);
}

// A lifetime, hold, throttle, period or window in seconds (docs/app-json.md#durations): a
// positive whole number of nanoseconds, at most 100 years (core/instant.h). The runtime counts
// time in nanoseconds and the proof reads the same integer, so a hand-edited 0.1234567891 (or
// 0, or 1e-10) is refused rather than rounded into something neither was told.
bool opt_duration(const Json& j, const std::string& path, const char* key,
                  std::optional<Nanos>* out, std::string* err) {
  if (!j.contains(key) || j[key].is_null()) return true;
  const Json& v = j[key];
  std::string where = path + "." + key;
  if (!v.is_number()) return fail(where + ": expected a number of seconds or null", err);
  double s = v.get<double>();
  if (!(s > 0)) return fail(where + ": expected a positive number of seconds", err);
  if (s > seconds_of(kLongestDuration))
    return fail(
        where + ": expected at most " + decimal_seconds(kLongestDuration) + " seconds (100 years)",
        err);
  *out = whole_nanos(s);
  if (!*out)
    return fail(where + ": " + shortest_decimal(s) +
                    " seconds is not a whole number of nanoseconds: write at most 9 digits "
                    "after the point",
                err);
  return true;
}

// The same for a duration that must be there.
bool get_duration(const Json& j, const std::string& path, const char* key, Nanos* out,
                  std::string* err) {
  std::optional<Nanos> d;
  if (!opt_duration(j, path, key, &d, err)) return false;
  if (!d) return fail(path + "." + key + ": expected a positive number of seconds", err);
  *out = *d;
  return true;
}

// A connection's list_bound: absent or null is 0 (any length), else a positive integer.
bool opt_list_bound(const Json& j, const std::string& path, int* out, std::string* err) {
  if (!j.contains("list_bound") || j["list_bound"].is_null()) return true;
  const Json& v = j["list_bound"];
  if (!v.is_number_integer() || v.get<int64_t>() < 1 || v.get<int64_t>() > 1000000)
    return fail(path + ".list_bound: expected an integer from 1 to 1000000, or null", err);
  *out = v.get<int>();
  return true;
}

bool opt_bool(const Json& j, const std::string& path, const char* key, bool* out,
              std::string* err) {
  if (!j.contains(key)) return true;
  if (!j[key].is_boolean()) return fail(path + "." + key + ": expected true or false", err);
  *out = j[key].get<bool>();
  return true;
}

const Json* array_member(const Json& j, const std::string& path, const char* key,
                         std::string* err) {
  const Json* v = member(j, path, key, err);
  if (v && !v->is_array()) {
    *err = path + "." + key + ": expected an array";
    return nullptr;
  }
  return v;
}

// Reads the array `key` of `j` (absent: empty unless `required`) with read_one(item, path, T*,
// err) per item; the items' paths are `prefix` + key + "[i]".
template <typename T, typename ReadOne>
bool read_array(const Json& j, const std::string& path, const std::string& prefix, const char* key,
                bool required, std::vector<T>* out, ReadOne read_one, std::string* err) {
  if (!required && !j.contains(key)) return true;
  const Json* arr = array_member(j, path, key, err);
  if (!arr) return false;
  for (size_t i = 0; i < arr->size(); ++i) {
    T item{};
    if (!read_one((*arr)[i], prefix + key + "[" + std::to_string(i) + "]", &item, err))
      return false;
    out->push_back(std::move(item));
  }
  return true;
}

bool read_string_item(const Json& j, const std::string& path, std::string* out, std::string* err) {
  if (!j.is_string()) return fail(path + ": expected a string", err);
  *out = j.get<std::string>();
  return true;
}

bool string_list(const Json& j, const std::string& path, const char* key,
                 std::vector<std::string>* out, std::string* err) {
  return read_array(j, path, path + ".", key, false, out, read_string_item, err);
}

bool read_location(const Json& j, const std::string& path, SourceLocation* loc, std::string* err) {
  if (!j.contains("loc")) return true;
  const Json& l = j["loc"];
  std::string p = path + ".loc";
  auto num = [&](const char* key, int* out) {
    if (!l.contains(key)) return true;
    if (!l[key].is_number_integer()) return fail(p + "." + key + ": expected an integer", err);
    *out = l[key].get<int>();
    return true;
  };
  std::string file;
  if (!opt_string(l, p, "file", &file, err)) return false;
  loc->file = file;
  return num("line", &loc->line) && num("column", &loc->column) &&
         num("end_line", &loc->end_line) && num("end_column", &loc->end_column);
}

bool read_source_map_entry(const Json& pair, const std::string& path, SourceMapEntry* out,
                           std::string* err) {
  if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number_integer() ||
      !pair[1].is_number_integer())
    return fail(path + ": expected [monitor_line, spec_line]", err);
  *out = {pair[0].get<int>(), pair[1].get<int>()};
  return true;
}

// `"body": ["(accept 3 ...)", ...]` (core/body_text.h); absent: not recorded (nullopt).
bool read_body(const Json& j, const std::string& path, std::optional<Body>* out, std::string* err) {
  if (!j.contains("body")) return true;
  const Json* arr = array_member(j, path, "body", err);
  if (!arr) return false;
  Body body;
  for (size_t i = 0; i < arr->size(); ++i) {
    std::string p = path + ".body[" + std::to_string(i) + "]", error;
    if (!(*arr)[i].is_string()) return fail(p + ": expected a string", err);
    std::optional<BodyStmt> s = parse_body_stmt((*arr)[i].get<std::string>(), &error);
    if (!s) return fail(p + ": " + error, err);
    body.push_back(std::move(*s));
  }
  *out = std::move(body);
  return true;
}

// A constraint is its text (grammar in core/constraint.h), the one representation.
bool read_constraint(const Json& j, const std::string& path, const char* key, Constraint* out,
                     std::string* err) {
  std::string text, error;
  if (!get_string(j, path, key, &text, err)) return false;
  std::optional<Constraint> parsed = parse_constraint(text, &error);
  if (!parsed) return fail(path + "." + key + ": " + error, err);
  *out = std::move(*parsed);
  return true;
}

// A monitor's SHA-256: required with a monitor (64 lower-case hex digits), absent without.
bool read_digest(const Json& j, const std::string& path, const std::string& monitor,
                 std::string* digest, std::string* err) {
  if (!opt_string(j, path, "monitor_sha256", digest, err)) return false;
  if (monitor.empty()) return true;
  bool hex =
      digest->size() == 64 && digest->find_first_not_of("0123456789abcdef") == std::string::npos;
  if (hex) return true;
  return fail(path + ".monitor_sha256: " +
                  (digest->empty() ? std::string("missing") : "not 64 lower-case hex digits") +
                  "; every monitor has the SHA-256 `arbc build` recorded (rebuild the app)",
              err);
}

// The claims script's digest: required with the script, as a monitor's is.
bool read_claims_digest(const Json& j, const std::string& path, App* app, std::string* err) {
  if (!opt_string(j, path, "claims_script_sha256", &app->claims_script_sha256, err)) return false;
  const std::string& d = app->claims_script_sha256;
  if (app->claims_script.empty() ||
      (d.size() == 64 && d.find_first_not_of("0123456789abcdef") == std::string::npos))
    return true;
  return fail(path + ".claims_script_sha256: " +
                  (d.empty() ? std::string("missing") : "not 64 lower-case hex digits") +
                  "; the claims script has the SHA-256 `arbc build` recorded (rebuild the app)",
              err);
}

bool read_type(const Json& j, const std::string& path, TypePtr* out, std::string* err) {
  std::string text, error;
  if (!get_string(j, path, "type", &text, err)) return false;
  *out = parse_type(text, &error);
  return *out ? true : fail(path + ".type: " + error, err);
}

// The file's version must be the one this arbc reads; then the app's name and description.
bool read_header(const Json& root, const std::string& r, App* app, std::string* err) {
  if (!root.is_object()) return fail(r + ": expected a JSON object", err);
  const Json* version = member(root, r, "schema_version", err);
  if (!version) return false;
  if (!version->is_number_integer()) return fail(r + ".schema_version: expected an integer", err);
  app->schema_version = version->get<int>();
  if (app->schema_version != kSchemaVersion)
    return fail(r + ".schema_version: this arbc reads version " + std::to_string(kSchemaVersion) +
                    ", the file has " + std::to_string(app->schema_version) +
                    "; rebuild it with this arbc",
                err);
  return get_string(root, r, "name", &app->name, err) &&
         opt_string(root, r, "description", &app->description, err) &&
         opt_string(root, r, "spec_file", &app->spec_file, err) &&
         opt_string(root, r, "claims_script", &app->claims_script, err) &&
         read_claims_digest(root, r, app, err);
}

// A named type of the spec (its name names the type on a DDS wire: dds/wire_types.h).
bool read_named_type(const Json& j, const std::string& p, NamedType* t, std::string* err) {
  return get_string(j, p, "name", &t->name, err) && read_type(j, p, &t->type, err) &&
         opt_string(j, p, "ros2", &t->ros2, err) && read_location(j, p, &t->loc, err);
}

bool read_port(const Json& j, const std::string& p, Port* port, std::string* err) {
  std::string dir;
  if (!get_string(j, p, "name", &port->name, err) || !get_string(j, p, "direction", &dir, err))
    return false;
  if (dir != "in" && dir != "out") return fail(p + ".direction: expected \"in\" or \"out\"", err);
  port->direction = dir == "in" ? Direction::In : Direction::Out;
  return read_type(j, p, &port->type, err) && read_location(j, p, &port->loc, err);
}

bool read_module(const Json& j, const std::string& p, Module* m, std::string* err) {
  return get_string(j, p, "name", &m->name, err) && opt_string(j, p, "doc", &m->doc, err) &&
         read_location(j, p, &m->loc, err) &&
         read_array(j, p, p + ".", "ports", true, &m->ports, read_port, err);
}

bool read_event(const Json& j, const std::string& p, Event* e, std::string* err) {
  if (j.contains("predicate")) {
    std::string text, error;
    if (!get_string(j, p, "predicate", &text, err)) return false;
    e->predicate = parse_body_expr(text, &error);
    if (!e->predicate) return fail(p + ".predicate: " + error, err);
  }
  return get_string(j, p, "name", &e->name, err) &&
         opt_duration(j, p, "lifetime", &e->lifetime, err) &&
         opt_string(j, p, "source", &e->source, err) && opt_string(j, p, "flag", &e->flag, err) &&
         opt_duration(j, p, "fail_open_after", &e->fail_open_after, err) &&
         read_location(j, p, &e->loc, err);
}

bool read_kind(const Json& j, const std::string& p, ConnectionKind* kind, std::string* err) {
  std::string text;
  if (!get_string(j, p, "kind", &text, err)) return false;
  if (text == "rule") {
    *kind = ConnectionKind::Rule;
  } else if (text == "feed") {
    *kind = ConnectionKind::Feed;
  } else if (text == "connect") {
    *kind = ConnectionKind::Connect;
  } else {
    return fail(p + ".kind: expected \"rule\", \"feed\" or \"connect\"", err);
  }
  return true;
}

// A connection: its ends and kind, its constraint and events, its timing, its monitor.
bool read_connection(const Json& j, const std::string& p, Connection* c, std::string* err) {
  return get_string(j, p, "name", &c->name, err) && get_string(j, p, "source", &c->source, err) &&
         get_string(j, p, "destination", &c->destination, err) && read_kind(j, p, &c->kind, err) &&
         opt_bool(j, p, "generated", &c->generated, err) &&
         read_constraint(j, p, "constraint", &c->constraint, err) &&
         string_list(j, p, "sets", &c->sets, err) && string_list(j, p, "unsets", &c->unsets, err) &&
         string_list(j, p, "must_set", &c->must_set, err) &&
         string_list(j, p, "must_unset", &c->must_unset, err) &&
         opt_string(j, p, "activity_event", &c->activity_event, err) &&
         string_list(j, p, "delivery_sets", &c->delivery_sets, err) &&
         string_list(j, p, "delivery_unsets", &c->delivery_unsets, err) &&
         opt_bool(j, p, "opaque", &c->opaque, err) && read_body(j, p, &c->body, err) &&
         opt_duration(j, p, "trig_interval", &c->trig_interval, err) &&
         opt_duration(j, p, "throttle", &c->throttle, err) &&
         opt_list_bound(j, p, &c->list_bound, err) &&
         opt_string(j, p, "monitor", &c->monitor, err) &&
         read_digest(j, p, c->monitor, &c->monitor_sha256, err) &&
         read_array(j, p, p + ".", "source_map", false, &c->source_map, read_source_map_entry,
                    err) &&
         read_location(j, p, &c->loc, err);
}

// An assertion: over events (`property`), or over data with `emitted` (core/body_text.h).
bool read_assertion(const Json& j, const std::string& p, Assertion* a, std::string* err) {
  if (!get_string(j, p, "rule", &a->rule, err) ||
      !read_constraint(j, p, "property", &a->property, err))
    return false;
  if (j.contains("emitted")) {
    std::string text, error;
    if (!get_string(j, p, "emitted", &text, err)) return false;
    a->emitted = parse_body_expr(text, &error);
    if (!a->emitted) return fail(p + ".emitted: " + error, err);
  }
  return read_location(j, p, &a->loc, err);
}

bool read_arbitrated_port(const Json& j, const std::string& p, ArbitratedPort* a,
                          std::string* err) {
  return get_string(j, p, "port", &a->port, err) &&
         opt_bool(j, p, "by_priority", &a->by_priority, err) &&
         opt_bool(j, p, "complete", &a->complete, err) &&
         string_list(j, p, "rules", &a->rules, err) && read_location(j, p, &a->loc, err) &&
         read_array(j, p, p + ".", "asserts", false, &a->asserts, read_assertion, err);
}

bool read_exclusive_group(const Json& j, const std::string& p, ExclusiveGroup* g,
                          std::string* err) {
  return string_list(j, p, "events", &g->events, err) && read_location(j, p, &g->loc, err);
}

bool read_invariant(const Json& j, const std::string& p, Invariant* inv, std::string* err) {
  return read_constraint(j, p, "formula", &inv->formula, err) &&
         read_location(j, p, &inv->loc, err);
}

// A response's trigger (`after`: a rule, or `event`), `stops` and `while` (its window is read
// as a spacing's; its `rule` is optional: without one, any rule of the port answers).
bool read_response(const Json& j, const std::string& p, TemporalProperty* t, std::string* err) {
  if (!opt_string(j, p, "rule", &t->rule, err)) return false;
  if (j.contains("event") == j.contains("after"))
    return fail(p + ": expected one trigger, \"after\" (a rule) or \"event\"", err);
  if (j.contains("event") ? !get_string(j, p, "event", &t->event, err)
                          : !get_string(j, p, "after", &t->other, err))
    return false;
  if (j.contains("stops")) {
    if (!j["stops"].is_boolean()) return fail(p + ".stops: expected true or false", err);
    t->stops = j["stops"].get<bool>();
    if (t->stops && !t->event.empty())
      return fail(p + ".stops: `stops` needs a trigger rule (\"after\"), not an event", err);
  }
  return !j.contains("while") || read_constraint(j, p, "while", &t->condition, err);
}

// `{"port": "M.p", "every": seconds}`: a source's rate.
bool read_rate(const Json& j, const std::string& p, SourceRate* r, std::string* err) {
  if (!get_string(j, p, "port", &r->port, err)) return false;
  return get_duration(j, p, "every", &r->period, err) && read_location(j, p, &r->loc, err);
}

// `{"kind": "spacing", "port": .., "rule": .., "window": seconds, "after": OTHER}` ("after"
// optional), `{"kind": "absence", .., "event": ..}`, `{"kind": "precedence", .., "after":
// OTHER}`, a response or a stability (docs/app-json.md).
bool read_temporal(const Json& j, const std::string& p, TemporalProperty* t, std::string* err) {
  std::string kind;
  if (!get_string(j, p, "kind", &kind, err)) return false;
  using K = TemporalProperty::Kind;
  bool known = false;
  for (K k : {K::Spacing, K::Absence, K::Precedence, K::Response, K::Stability}) {
    if (kind == temporal_kind_name(k)) t->kind = k, known = true;
  }
  if (!known)
    return fail(p + ".kind: expected \"spacing\", \"absence\", \"precedence\", \"response\" or "
                    "\"stability\"",
                err);
  if (!get_string(j, p, "port", &t->port, err)) return false;
  if (t->kind != K::Stability && t->kind != K::Response && !get_string(j, p, "rule", &t->rule, err))
    return false;
  if (t->kind == K::Spacing || t->kind == K::Response || t->kind == K::Stability) {
    if (!get_duration(j, p, "window", &t->window, err)) return false;
  }
  if (t->kind == K::Spacing && !opt_string(j, p, "after", &t->other, err)) return false;
  if (t->kind == K::Absence && !get_string(j, p, "event", &t->event, err)) return false;
  if (t->kind == K::Precedence && !get_string(j, p, "after", &t->other, err)) return false;
  if (t->kind == K::Response && !read_response(j, p, t, err)) return false;
  return read_location(j, p, &t->loc, err);
}

// `{"event": .., "port": .., "after": RULE, "until": RULE}`, `until` optional, or the timed
// form `{"event": .., "port": .., "after": RULE, "absent_for": seconds}`
// (docs/app-json.md#assumptions).
bool read_assumption(const Json& j, const std::string& p, Assumption* a, std::string* err) {
  if (!get_string(j, p, "event", &a->event, err) || !get_string(j, p, "port", &a->port, err) ||
      !get_string(j, p, "after", &a->after, err))
    return false;
  if (!opt_string(j, p, "until", &a->until, err)) return false;
  if (!opt_duration(j, p, "absent_for", &a->absent_for, err)) return false;
  if (a->absent_for && !a->until.empty())
    return fail(p + ": an assumption has \"until\" or \"absent_for\", not both", err);
  return read_location(j, p, &a->loc, err);
}

// A resource: its name, its ports and, optionally, the predicate saying which commands use it.
bool read_resource(const Json& j, const std::string& p, Resource* res, std::string* err) {
  if (!get_string(j, p, "name", &res->name, err) || !string_list(j, p, "ports", &res->ports, err))
    return false;
  if (j.contains("uses")) {
    std::string text, error;
    if (!get_string(j, p, "uses", &text, err)) return false;
    res->uses = parse_body_expr(text, &error);
    if (!res->uses) return fail(p + ".uses: " + error, err);
  }
  return read_location(j, p, &res->loc, err);
}

// The model in `root`, section by section; nullopt and *err at the first bad value.
std::optional<App> read_app(const Json& root, std::string* err) {
  App app;
  const std::string r = "app.json";
  bool ok = read_header(root, r, &app, err) &&
            read_array(root, r, "", "types", false, &app.types, read_named_type, err) &&
            read_array(root, r, "", "modules", true, &app.modules, read_module, err) &&
            read_array(root, r, "", "events", false, &app.events, read_event, err) &&
            read_array(root, r, "", "connections", true, &app.connections, read_connection, err) &&
            read_array(root, r, "", "arbitrated_ports", false, &app.arbitrated_ports,
                       read_arbitrated_port, err) &&
            read_array(root, r, "", "exclusive_groups", false, &app.exclusive_groups,
                       read_exclusive_group, err) &&
            read_array(root, r, "", "invariants", false, &app.invariants, read_invariant, err) &&
            read_array(root, r, "", "resources", false, &app.resources, read_resource, err) &&
            read_array(root, r, "", "temporal", false, &app.temporal, read_temporal, err) &&
            read_array(root, r, "", "assumptions", false, &app.assumptions, read_assumption, err) &&
            read_array(root, r, "", "rates", false, &app.rates, read_rate, err);
  if (!ok) return std::nullopt;
  type_bodies(app);  // the types the text leaves out, as lowering gives them (body_types.h)
  return app;
}

// read_app with the library's exceptions caught: they mean a bug above (a value read before
// its type was checked), not a bad file, but still end in an error rather than a crash.
std::optional<App> read_app_checked(const Json& root, std::string* err) {
  try {
    return read_app(root, err);
  } catch (const Json::exception& e) {
    *err = std::string("app.json: ") + e.what();
    return std::nullopt;
  }
}

// The readers above name a bad value by its path written out ("connections[3].source: ...",
// "app.json.schema_version: ..."), made of the schema's own keys (none holds '.', '[' or ':')
// and of indices, so it splits back into the path json_place takes (core/json_place.h). Sets
// *message to the error without the file's own name; the path is {} for the whole file.
std::vector<std::string> path_of(const std::string& err, std::string* message) {
  std::string_view rest = err;
  for (std::string_view file : {"app.json: ", "app.json."}) {
    if (rest.substr(0, file.size()) == file) rest.remove_prefix(file.size());
  }
  *message = std::string(rest);
  std::vector<std::string> path;
  size_t end = rest.find(": ");
  if (end == std::string_view::npos) return path;
  std::string_view written = rest.substr(0, end);
  for (size_t i = 0; i < written.size();) {
    if (written[i] == '.') {
      ++i;
    } else if (written[i] == '[') {
      size_t close = written.find(']', i);
      if (close == std::string_view::npos) return {};
      path.emplace_back(written.substr(i + 1, close - i - 1));
      i = close + 1;
    } else {
      size_t next = written.find_first_of(".[", i);
      if (next == std::string_view::npos) next = written.size();
      path.emplace_back(written.substr(i, next - i));
      i = next;
    }
  }
  return path;
}

}  // namespace

std::optional<App> from_app_json(std::string_view text, std::string* err) {
  Json root;
  if (JsonParseError e; !parse_json(text, &root, &e)) {
    std::string where =
        e.line ? "line " + std::to_string(e.line) + ", column " + std::to_string(e.column) + ": "
               : "";
    *err = where + json_error_message(e);
    return std::nullopt;
  }
  return read_app_checked(root, err);
}

std::optional<App> from_app_json(std::string_view text, const std::string& file,
                                 Diagnostic* error) {
  Json root;
  if (JsonParseError e; !parse_json(text, &root, &e)) {
    *error = json_syntax_diagnostic(file, e);
    error->id = diag::AppJson.text();
    return std::nullopt;
  }
  std::string err;
  std::optional<App> app = read_app_checked(root, &err);
  if (app) return app;
  std::string message;
  std::vector<std::string> path = path_of(err, &message);
  // A value that is missing is placed at the object that lacks it: the nearest part of the
  // path that the text has.
  while (!path.empty() && !json_place(text, path)) path.pop_back();
  *error = json_diagnostic(file, text, path, JsonPart::Value, message);
  error->id = diag::AppJson.text();
  return std::nullopt;
}

}  // namespace arbc::model
