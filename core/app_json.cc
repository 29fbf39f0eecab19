#include "core/app_json.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "core/body_text.h"

namespace arbc::model {

using Json = nlohmann::ordered_json;

namespace {

// Reading: each helper throws LoadError with the JSON path of the offending value.
struct LoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const Json& member(const Json& j, const std::string& path, const char* key) {
  if (!j.is_object()) throw LoadError(path + ": expected an object");
  auto it = j.find(key);
  if (it == j.end()) throw LoadError(path + ": missing \"" + key + "\"");
  return *it;
}

std::string get_string(const Json& j, const std::string& path, const char* key) {
  const Json& v = member(j, path, key);
  if (!v.is_string()) throw LoadError(path + "." + key + ": expected a string");
  return v.get<std::string>();
}

std::string opt_string(const Json& j, const std::string& path, const char* key) {
  if (!j.contains(key)) return {};
  return get_string(j, path, key);
}

std::optional<double> opt_number(const Json& j, const std::string& path, const char* key) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  if (!j[key].is_number()) throw LoadError(path + "." + key + ": expected a number or null");
  return j[key].get<double>();
}

bool opt_bool(const Json& j, const std::string& path, const char* key) {
  if (!j.contains(key)) return false;
  if (!j[key].is_boolean()) throw LoadError(path + "." + key + ": expected true or false");
  return j[key].get<bool>();
}

const Json& array_member(const Json& j, const std::string& path, const char* key) {
  const Json& v = member(j, path, key);
  if (!v.is_array()) throw LoadError(path + "." + key + ": expected an array");
  return v;
}

std::vector<std::string> string_list(const Json& j, const std::string& path, const char* key) {
  std::vector<std::string> out;
  if (!j.contains(key)) return out;
  const Json& arr = array_member(j, path, key);
  for (size_t i = 0; i < arr.size(); ++i) {
    if (!arr[i].is_string())
      throw LoadError(path + "." + key + "[" + std::to_string(i) + "]: expected a string");
    out.push_back(arr[i].get<std::string>());
  }
  return out;
}

SourceLocation read_location(const Json& j, const std::string& path) {
  SourceLocation loc;
  if (!j.contains("loc")) return loc;
  const Json& l = j["loc"];
  std::string p = path + ".loc";
  loc.file = opt_string(l, p, "file");
  auto num = [&](const char* key) {
    if (!l.contains(key)) return 0;
    if (!l[key].is_number_integer()) throw LoadError(p + "." + key + ": expected an integer");
    return l[key].get<int>();
  };
  loc.line = num("line");
  loc.column = num("column");
  loc.end_line = num("end_line");
  loc.end_column = num("end_column");
  return loc;
}

// `"source_map": [[monitor_line, spec_line], ...]`; optional (older files have none).
std::vector<SourceMapEntry> read_source_map(const Json& j, const std::string& path) {
  std::vector<SourceMapEntry> out;
  if (!j.contains("source_map")) return out;
  const Json& arr = array_member(j, path, "source_map");
  for (size_t i = 0; i < arr.size(); ++i) {
    const Json& pair = arr[i];
    if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number_integer() ||
        !pair[1].is_number_integer())
      throw LoadError(path + ".source_map[" + std::to_string(i) +
                      "]: expected [monitor_line, spec_line]");
    out.push_back({pair[0].get<int>(), pair[1].get<int>()});
  }
  return out;
}

// `"body": ["(accept 3 ...)", ...]` (core/body_text.h); absent: not recorded.
std::optional<Body> read_body(const Json& j, const std::string& path) {
  if (!j.contains("body")) return std::nullopt;
  const Json& arr = array_member(j, path, "body");
  Body body;
  for (size_t i = 0; i < arr.size(); ++i) {
    std::string p = path + ".body[" + std::to_string(i) + "]";
    if (!arr[i].is_string()) throw LoadError(p + ": expected a string");
    std::string err;
    std::optional<BodyStmt> s = parse_body_stmt(arr[i].get<std::string>(), &err);
    if (!s) throw LoadError(p + ": " + err);
    body.push_back(std::move(*s));
  }
  return body;
}

// A constraint is its text (grammar in core/constraint.h), the one representation.
Constraint read_constraint(const Json& j, const std::string& path, const char* key) {
  std::string text = get_string(j, path, key);
  ConstraintParse parsed = parse_constraint(text);
  if (!parsed.ok)
    throw LoadError(path + "." + key + ": " + parsed.error + " at offset " +
                    std::to_string(parsed.offset));
  return parsed.constraint;
}

// A monitor's SHA-256: required with a monitor (64 lower-case hex digits), absent without.
std::string read_digest(const Json& j, const std::string& path, const std::string& monitor) {
  std::string digest = opt_string(j, path, "monitor_sha256");
  if (monitor.empty()) return digest;
  bool hex =
      digest.size() == 64 && digest.find_first_not_of("0123456789abcdef") == std::string::npos;
  if (!hex)
    throw LoadError(path + ".monitor_sha256: " +
                    (digest.empty() ? std::string("missing") : "not 64 lower-case hex digits") +
                    "; every monitor has the SHA-256 `arbc build` recorded (rebuild the app)");
  return digest;
}

TypePtr read_type(const Json& j, const std::string& path) {
  std::string text = get_string(j, path, "type");
  std::string error;
  TypePtr t = parse_type(text, &error);
  if (!t) throw LoadError(path + ".type: " + error);
  return t;
}

App read_app(const Json& root) {
  App app;
  const std::string r = "app.json";
  if (!root.is_object()) throw LoadError(r + ": expected a JSON object");
  const Json& version = member(root, r, "schema_version");
  if (!version.is_number_integer()) throw LoadError(r + ".schema_version: expected an integer");
  app.schema_version = version.get<int>();
  if (app.schema_version != kSchemaVersion)
    throw LoadError(r + ".schema_version: this arbc reads version " +
                    std::to_string(kSchemaVersion) + ", the file has " +
                    std::to_string(app.schema_version) + "; rebuild it with this arbc");
  app.name = get_string(root, r, "name");
  app.description = opt_string(root, r, "description");
  app.spec_file = opt_string(root, r, "spec_file");

  const Json& modules = array_member(root, r, "modules");
  for (size_t i = 0; i < modules.size(); ++i) {
    std::string p = "modules[" + std::to_string(i) + "]";
    Module m;
    m.name = get_string(modules[i], p, "name");
    m.doc = opt_string(modules[i], p, "doc");
    m.loc = read_location(modules[i], p);
    const Json& ports = array_member(modules[i], p, "ports");
    for (size_t k = 0; k < ports.size(); ++k) {
      std::string pp = p + ".ports[" + std::to_string(k) + "]";
      Port port;
      port.name = get_string(ports[k], pp, "name");
      std::string dir = get_string(ports[k], pp, "direction");
      if (dir != "in" && dir != "out")
        throw LoadError(pp + ".direction: expected \"in\" or \"out\"");
      port.direction = dir == "in" ? Direction::In : Direction::Out;
      port.type = read_type(ports[k], pp);
      port.loc = read_location(ports[k], pp);
      m.ports.push_back(std::move(port));
    }
    app.modules.push_back(std::move(m));
  }

  if (root.contains("events")) {
    const Json& events = array_member(root, r, "events");
    for (size_t i = 0; i < events.size(); ++i) {
      std::string p = "events[" + std::to_string(i) + "]";
      Event e;
      e.name = get_string(events[i], p, "name");
      e.lifetime = opt_number(events[i], p, "lifetime");
      e.source = opt_string(events[i], p, "source");
      e.loc = read_location(events[i], p);
      app.events.push_back(std::move(e));
    }
  }

  const Json& connections = array_member(root, r, "connections");
  for (size_t i = 0; i < connections.size(); ++i) {
    std::string p = "connections[" + std::to_string(i) + "]";
    const Json& cj = connections[i];
    Connection c;
    c.name = get_string(cj, p, "name");
    c.source = get_string(cj, p, "source");
    c.destination = get_string(cj, p, "destination");
    std::string kind = get_string(cj, p, "kind");
    if (kind == "rule")
      c.kind = ConnectionKind::Rule;
    else if (kind == "feed")
      c.kind = ConnectionKind::Feed;
    else if (kind == "connect")
      c.kind = ConnectionKind::Connect;
    else
      throw LoadError(p + ".kind: expected \"rule\", \"feed\" or \"connect\"");
    c.generated = opt_bool(cj, p, "generated");
    c.constraint = read_constraint(cj, p, "constraint");
    c.sets = string_list(cj, p, "sets");
    c.unsets = string_list(cj, p, "unsets");
    c.must_set = string_list(cj, p, "must_set");
    c.must_unset = string_list(cj, p, "must_unset");
    c.activity_event = opt_string(cj, p, "activity_event");
    c.opaque = opt_bool(cj, p, "opaque");
    c.body = read_body(cj, p);
    c.trig_interval = opt_number(cj, p, "trig_interval");
    c.throttle = opt_number(cj, p, "throttle");
    c.monitor = opt_string(cj, p, "monitor");
    c.monitor_sha256 = read_digest(cj, p, c.monitor);
    c.source_map = read_source_map(cj, p);
    c.loc = read_location(cj, p);
    app.connections.push_back(std::move(c));
  }

  if (root.contains("arbitrated_ports")) {
    const Json& ports = array_member(root, r, "arbitrated_ports");
    for (size_t i = 0; i < ports.size(); ++i) {
      std::string p = "arbitrated_ports[" + std::to_string(i) + "]";
      ArbitratedPort a;
      a.port = get_string(ports[i], p, "port");
      a.by_priority = opt_bool(ports[i], p, "by_priority");
      a.complete = opt_bool(ports[i], p, "complete");
      a.rules = string_list(ports[i], p, "rules");
      a.loc = read_location(ports[i], p);
      if (ports[i].contains("asserts")) {
        const Json& asserts = array_member(ports[i], p, "asserts");
        for (size_t k = 0; k < asserts.size(); ++k) {
          std::string ap = p + ".asserts[" + std::to_string(k) + "]";
          Assertion as;
          as.rule = get_string(asserts[k], ap, "rule");
          as.property = read_constraint(asserts[k], ap, "property");
          as.loc = read_location(asserts[k], ap);
          a.asserts.push_back(std::move(as));
        }
      }
      app.arbitrated_ports.push_back(std::move(a));
    }
  }

  if (root.contains("exclusive_groups")) {
    const Json& groups = array_member(root, r, "exclusive_groups");
    for (size_t i = 0; i < groups.size(); ++i) {
      std::string p = "exclusive_groups[" + std::to_string(i) + "]";
      ExclusiveGroup g;
      g.events = string_list(groups[i], p, "events");
      g.loc = read_location(groups[i], p);
      app.exclusive_groups.push_back(std::move(g));
    }
  }
  if (root.contains("invariants")) {
    const Json& invs = array_member(root, r, "invariants");
    for (size_t i = 0; i < invs.size(); ++i) {
      std::string p = "invariants[" + std::to_string(i) + "]";
      Invariant inv;
      inv.formula = read_constraint(invs[i], p, "formula");
      inv.loc = read_location(invs[i], p);
      app.invariants.push_back(std::move(inv));
    }
  }
  if (root.contains("resources")) {
    const Json& rs = array_member(root, r, "resources");
    for (size_t i = 0; i < rs.size(); ++i) {
      std::string p = "resources[" + std::to_string(i) + "]";
      Resource res;
      res.name = get_string(rs[i], p, "name");
      res.ports = string_list(rs[i], p, "ports");
      if (rs[i].contains("uses")) {
        std::string err;
        res.uses = parse_body_expr(get_string(rs[i], p, "uses"), &err);
        if (!res.uses) throw LoadError(p + ".uses: " + err);
      }
      res.loc = read_location(rs[i], p);
      app.resources.push_back(std::move(res));
    }
  }
  return app;
}

// Line and column (1-based, in bytes) of byte offset `offset` of `text`.
std::string position_of(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t line = 1, column = 1;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Parses text; on a syntax error says where ("not valid JSON at line 3, column 5: ...").
// nlohmann-json reports syntax errors only as exceptions: caught here, at the boundary.
bool parse_json(std::string_view text, Json* root, std::string* err) {
  try {
    *root = Json::parse(text.begin(), text.end());
    return true;
  } catch (const Json::parse_error& e) {
    // e.byte is one past the offending byte; the library's own text repeats the position.
    std::string what = e.what();
    size_t colon = what.find(": ", what.find("parse error"));
    std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
    *err = "not valid JSON at " + position_of(text, e.byte > 0 ? e.byte - 1 : 0) + ": " + detail;
  }
  return false;
}

}  // namespace

AppLoad from_app_json(std::string_view text) {
  AppLoad result;
  Json root;
  if (!parse_json(text, &root, &result.error)) return result;
  try {
    result.app = read_app(root);
    result.ok = true;
  } catch (const LoadError& e) {
    result.error = e.what();
  } catch (const Json::exception& e) {
    result.error = std::string("app.json: ") + e.what();
  }
  return result;
}

}  // namespace arbc::model
