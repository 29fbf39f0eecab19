#include "dds/deployment.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/json_parse.h"

namespace arbc::dds {

namespace {

using Json = nlohmann::json;

const char* const kBuiltinTypes[] = {"bool", "int", "float", "string", "vec3"};

// An object of strings: "topics" and "types".
bool read_string_map(const Json& j, const std::string& where,
                     std::map<std::string, std::string>* out, std::string* error) {
  if (!j.is_object()) {
    *error = where + ": expected an object of strings, e.g. {\"Module.port\": \"/topic\"}";
    return false;
  }
  for (const auto& [key, value] : j.items()) {
    if (!value.is_string() || value.get<std::string>().empty()) {
      *error = where + "." + key + ": expected a non-empty string";
      return false;
    }
    (*out)[key] = value.get<std::string>();
  }
  return true;
}

bool read_integer(const Json& j, const std::string& where, int low, int high, int* out,
                  std::string* error) {
  if (!j.is_number_integer() || j.get<int64_t>() < low || j.get<int64_t>() > high) {
    *error =
        where + ": expected an integer from " + std::to_string(low) + " to " + std::to_string(high);
    return false;
  }
  *out = static_cast<int>(j.get<int64_t>());
  return true;
}

bool read_qos(const Json& j, const std::string& where, Deployment* out, std::string* error) {
  if (!j.is_object()) {
    *error = where + ": expected an object such as {\"depth\": 100}";
    return false;
  }
  for (const auto& [key, value] : j.items()) {
    if (key != "depth") {
      *error = where + ": unknown key \"" + key + "\" (the qos keys are: depth)";
      return false;
    }
    if (!read_integer(value, where + ".depth", 1, 100000, &out->depth, error)) return false;
  }
  return true;
}

// One top-level key of the file.
bool read_key(const std::string& key, const Json& value, const std::string& where, Deployment* out,
              std::string* error) {
  if (key == "domain") {
    int domain = 0;
    // DDS maps a domain to UDP ports; 232 is the largest the default port mapping allows.
    if (!read_integer(value, where, 0, 232, &domain, error)) return false;
    out->domain = domain;
    return true;
  }
  if (key == "ros2") {
    if (!value.is_boolean()) {
      *error = where + ": expected true or false";
      return false;
    }
    out->ros2 = value.get<bool>();
    return true;
  }
  if (key == "topics") return read_string_map(value, where, &out->topics, error);
  if (key == "types") return read_string_map(value, where, &out->types, error);
  if (key == "qos") return read_qos(value, where, out, error);
  *error = where + ": unknown key (the keys are: domain, ros2, topics, types, qos)";
  return false;
}

}  // namespace

bool parse_deployment(std::string_view text, const std::string& path, Deployment* out,
                      std::string* error) {
  Json root;
  if (JsonParseError e; !parse_json(text, &root, &e)) {
    std::string where = e.line ? ":" + std::to_string(e.line) + ":" + std::to_string(e.column) : "";
    *error = path + where + ": not valid JSON (" + e.detail + ")";
    return false;
  }
  if (!root.is_object()) {
    *error = path + ": expected a JSON object with the keys domain, ros2, topics, types, qos";
    return false;
  }
  Deployment d;
  d.path = path;
  for (const auto& [key, value] : root.items()) {
    if (!read_key(key, value, path + ": " + key, &d, error)) return false;
  }
  *out = std::move(d);
  return true;
}

bool read_deployment(const std::string& path, Deployment* out, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *error = path + ": cannot read the deployment file";
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_deployment(text.str(), path, out, error);
}

bool check_deployment(const Deployment& d, const model::App& app, std::string* error) {
  std::string file = d.path.empty() ? "the deployment" : d.path;
  std::map<std::string, std::string> ports_of_topic;
  for (const auto& [port, topic] : d.topics) {
    if (!app.find_port(port)) {
      *error = file + ": topics: \"" + port + "\" is not a port of app " + app.name +
               " (write Module.port as in the spec)";
      return false;
    }
    auto [it, fresh] = ports_of_topic.emplace(topic, port);
    if (!fresh) {
      *error = file + ": topics: \"" + port + "\" and \"" + it->second + "\" are both on topic " +
               topic + "; give each port its own topic";
      return false;
    }
  }
  std::set<std::string> known(std::begin(kBuiltinTypes), std::end(kBuiltinTypes));
  for (const model::NamedType& t : app.types) known.insert(t.name);
  for (const auto& [name, wire] : d.types) {
    if (!known.count(name)) {
      std::string names;
      for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
      *error = file + ": types: \"" + name + "\" is not a type of app " + app.name +
               " (the types are: " + names + ")";
      return false;
    }
  }
  return true;
}

}  // namespace arbc::dds
