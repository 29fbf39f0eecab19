#include "dds/deployment.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/json_diagnostic.h"
#include "core/ros2_known_messages.h"
#include "core/suggest.h"
#include "dds/msg_layout.h"

namespace arbc::dds {

namespace {

using Json = nlohmann::json;
using Path = std::vector<std::string>;

const char* const kBuiltinTypes[] = {"bool", "int", "float", "string", "vec3"};

// "; did you mean "x"?" when one of `candidates` is a plausible typo of `name`, else nothing.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  auto meant = closest_name(name, candidates);
  return meant ? "; did you mean \"" + *meant + "\"?" : "";
}

// The problems of one file, each a diagnostic at the key or value it is about
// (core/json_diagnostic.h); one that cannot be placed is at the file.
class Problems {
 public:
  Problems(const std::string& file, std::string_view text, std::vector<Diagnostic>* out)
      : file_(file), text_(text), out_(out), first_(out->size()) {}

  void at(const Path& path, JsonPart part, std::string message) {
    out_->push_back(json_diagnostic(file_, text_, path, part, std::move(message)));
  }
  void value(const Path& path, std::string message) { at(path, JsonPart::Value, message); }
  void key(const Path& path, std::string message) { at(path, JsonPart::Key, message); }
  // Attaches a note at another value to the last problem.
  void note_value(const Path& path, std::string message) {
    Problems notes(file_, text_, &out_->back().notes);
    notes.value(path, std::move(message));
    out_->back().notes.back().severity = Severity::Note;
  }

  // False when some problem was found; puts them in the file's order (the library hands keys
  // over sorted by name).
  bool finish() {
    std::stable_sort(out_->begin() + static_cast<std::ptrdiff_t>(first_), out_->end(),
                     [](const Diagnostic& a, const Diagnostic& b) {
                       return std::pair(a.loc.line, a.loc.column) <
                              std::pair(b.loc.line, b.loc.column);
                     });
    return out_->size() == first_;
  }

 private:
  std::string file_;
  std::string_view text_;
  std::vector<Diagnostic>* out_;
  size_t first_;
};

// An object of strings: "topics" and "types".
void read_string_map(const Json& j, const std::string& key, const char* example,
                     std::map<std::string, std::string>* out, Problems& problems) {
  if (!j.is_object()) {
    problems.value({key}, key + ": expected an object of strings, e.g. " + example);
    return;
  }
  for (const auto& [name, value] : j.items()) {
    if (!value.is_string() || value.get<std::string>().empty()) {
      problems.value({key, name}, key + ": \"" + name + "\": expected a non-empty string");
      continue;
    }
    (*out)[name] = value.get<std::string>();
  }
}

bool read_integer(const Json& j, const Path& path, const std::string& name, int low, int high,
                  int* out, Problems& problems) {
  if (!j.is_number_integer() || j.get<int64_t>() < low || j.get<int64_t>() > high) {
    problems.value(path, name + ": expected an integer from " + std::to_string(low) + " to " +
                             std::to_string(high));
    return false;
  }
  *out = static_cast<int>(j.get<int64_t>());
  return true;
}

// One of a port's QoS words: `key` is "reliability" or "durability", `other` the word that
// turns the setting on ("best_effort", "transient_local"), `usual` the default's word.
void read_qos_word(const Json& j, const Path& path, const char* usual, const char* other, bool* out,
                   Problems& problems) {
  std::string word = j.is_string() ? j.get<std::string>() : "";
  if (word != usual && word != other) {
    problems.value(path, "qos: ports: \"" + path[2] + "\": " + path[3] + ": expected \"" + usual +
                             "\" or \"" + other + "\"");
    return;
  }
  *out = word == other;
}

// "ports": {"Module.port": {"reliability": ..., "durability": ...}}; the ports are checked
// against the app by check_deployment.
void read_port_qos(const Json& j, Deployment* out, Problems& problems) {
  if (!j.is_object()) {
    problems.value({"qos", "ports"},
                   "qos: ports: expected an object such as "
                   "{\"Bumper.state\": {\"reliability\": \"best_effort\"}}");
    return;
  }
  for (const auto& [port, settings] : j.items()) {
    if (!settings.is_object()) {
      problems.value(
          {"qos", "ports", port},
          "qos: ports: \"" + port + "\": expected an object with the keys reliability, durability");
      continue;
    }
    PortQos& qos = out->port_qos[port];
    for (const auto& [key, value] : settings.items()) {
      Path path{"qos", "ports", port, key};
      if (key == "reliability") {
        read_qos_word(value, path, "reliable", "best_effort", &qos.best_effort, problems);
      } else if (key == "durability") {
        read_qos_word(value, path, "volatile", "transient_local", &qos.transient_local, problems);
      } else {
        problems.key(path, "qos: ports: \"" + port + "\": unknown key \"" + key + "\"" +
                               did_you_mean(key, {"reliability", "durability"}) +
                               " (the keys are: reliability, durability)");
      }
    }
  }
}

void read_qos(const Json& j, Deployment* out, Problems& problems) {
  if (!j.is_object()) {
    problems.value({"qos"}, "qos: expected an object such as {\"depth\": 100}");
    return;
  }
  for (const auto& [key, value] : j.items()) {
    if (key == "depth") {
      read_integer(value, {"qos", "depth"}, "qos.depth", 1, 100000, &out->depth, problems);
    } else if (key == "ports") {
      read_port_qos(value, out, problems);
    } else {
      problems.key({"qos", key}, "qos: unknown key \"" + key + "\"" +
                                     did_you_mean(key, {"depth", "ports"}) +
                                     " (the qos keys are: depth, ports)");
    }
  }
}

// "status": false, or {"diagnostics": "/topic", "topics": {"Module.port": "/topic"}}; the
// ports are checked against the app by check_deployment.
void read_status(const Json& j, Deployment* out, Problems& problems) {
  if (j.is_boolean()) {
    out->status = j.get<bool>();
    return;
  }
  if (!j.is_object()) {
    problems.value({"status"},
                   "status: expected false (no status topics) or an object such as "
                   "{\"diagnostics\": \"/diagnostics\"}");
    return;
  }
  for (const auto& [key, value] : j.items()) {
    if (key == "diagnostics") {
      if (value.is_string() && !value.get<std::string>().empty()) {
        out->diagnostics_topic = value.get<std::string>();
      } else {
        problems.value({"status", key}, "status: diagnostics: expected a non-empty topic name");
      }
    } else if (key == "topics") {
      if (!value.is_object()) {
        problems.value({"status", key},
                       "status: topics: expected an object of strings, e.g. "
                       "{\"Base.cmd_vel\": \"/mux/active\"}");
        continue;
      }
      for (const auto& [port, topic] : value.items()) {
        if (!topic.is_string() || topic.get<std::string>().empty()) {
          problems.value({"status", key, port},
                         "status: topics: \"" + port + "\": expected a non-empty string");
          continue;
        }
        out->status_topics[port] = topic.get<std::string>();
      }
    } else {
      problems.key({"status", key}, "status: unknown key \"" + key + "\"" +
                                        did_you_mean(key, {"diagnostics", "topics"}) +
                                        " (the status keys are: diagnostics, topics)");
    }
  }
}

// One top-level key of the file.
void read_key(const std::string& key, const Json& value, Deployment* out, Problems& problems) {
  if (key == "domain") {
    int domain = 0;
    // DDS maps a domain to UDP ports; 232 is the largest the default port mapping allows.
    if (read_integer(value, {key}, key, 0, 232, &domain, problems)) out->domain = domain;
  } else if (key == "ros2") {
    if (value.is_boolean()) {
      out->ros2 = value.get<bool>();
    } else {
      problems.value({key}, "ros2: expected true or false");
    }
  } else if (key == "topics") {
    read_string_map(value, key, "{\"Module.port\": \"/topic\"}", &out->topics, problems);
  } else if (key == "types") {
    read_string_map(value, key, "{\"Twist\": \"geometry_msgs/msg/Twist\"}", &out->types, problems);
  } else if (key == "qos") {
    read_qos(value, out, problems);
  } else if (key == "status") {
    read_status(value, out, problems);
  } else {
    problems.key({key},
                 "unknown key \"" + key + "\"" +
                     did_you_mean(key, {"domain", "ros2", "topics", "types", "qos", "status"}) +
                     " (the keys are: domain, ros2, topics, types, qos, status; "
                     "docs/distributed.md#the-deployment-file)");
  }
}

// Each "status" "topics" key is an arbitrated port: a status is about a port's rules.
void check_status_topics(const Deployment& d, const model::App& app, Problems& problems) {
  std::vector<std::string> arbitrated;
  for (const model::ArbitratedPort& a : app.arbitrated_ports) arbitrated.push_back(a.port);
  for (const auto& [port, topic] : d.status_topics) {
    if (std::find(arbitrated.begin(), arbitrated.end(), port) == arbitrated.end())
      problems.key({"status", "topics", port},
                   "status: topics: \"" + port + "\" is not an arbitrated port of app " + app.name +
                       did_you_mean(port, arbitrated) +
                       " (a status topic is about the rules of a port's `arbitrate` block)");
  }
}

Diagnostic at_file(const std::string& path, std::string message) {
  Diagnostic d;
  d.loc.file = path;
  d.message = std::move(message);
  return d;
}

}  // namespace

bool parse_deployment(std::string_view text, const std::string& path, Deployment* out,
                      std::vector<Diagnostic>* errors) {
  Json root;
  if (JsonParseError e; !parse_json(text, &root, &e)) {
    errors->push_back(json_syntax_diagnostic(path, e));
    return false;
  }
  Problems problems(path, text, errors);
  if (!root.is_object()) {
    problems.value({},
                   "expected a JSON object with the keys domain, ros2, topics, types, qos, "
                   "status");
    return problems.finish();
  }
  Deployment d;
  d.path = path;
  d.text = std::string(text);
  for (const auto& [key, value] : root.items()) read_key(key, value, &d, problems);
  if (!problems.finish()) return false;
  *out = std::move(d);
  return true;
}

bool read_deployment(const std::string& path, Deployment* out, std::vector<Diagnostic>* errors) {
  // Said apart, so that a directory is not reported as a JSON syntax error at 1:1.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    errors->push_back(at_file(path,
                              "is a directory, not a deployment file (a JSON file such as "
                              "teleop.deploy.json; docs/distributed.md#the-deployment-file)"));
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    errors->push_back(at_file(path, std::string("cannot read the deployment file") +
                                        (std::filesystem::exists(path, ec) ? " (permission denied?)"
                                                                           : " (no such file)")));
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_deployment(text.str(), path, out, errors);
}

bool check_deployment(const Deployment& d, const model::App& app, std::vector<Diagnostic>* errors) {
  Problems problems(d.path.empty() ? "the deployment" : d.path, d.text, errors);
  std::vector<std::string> all_ports;
  for (const model::Module& m : app.modules) {
    for (const model::Port& p : m.ports) all_ports.push_back(m.name + "." + p.name);
  }
  std::map<std::string, std::string> ports_of_topic;
  for (const auto& [port, topic] : d.topics) {
    if (!app.find_port(port)) {
      problems.key({"topics", port}, "topics: \"" + port + "\" is not a port of app " + app.name +
                                         did_you_mean(port, all_ports) +
                                         " (write Module.port as in the spec)");
      continue;
    }
    auto [it, fresh] = ports_of_topic.emplace(topic, port);
    if (!fresh) {
      problems.value({"topics", port}, "topics: \"" + port + "\" and \"" + it->second +
                                           "\" are both on topic " + topic +
                                           "; give each port its own topic");
      problems.note_value({"topics", it->second}, "the topic of \"" + it->second + "\"");
    }
  }
  // A topic the file gives may also be another port's default (Module/port): the transport
  // would find that only when it opens, naming no file.
  std::map<std::string, std::string> port_of_wire;
  for (const model::Module& m : app.modules) {
    for (const model::Port& p : m.ports) {
      std::string port = m.name + "." + p.name;
      auto [it, fresh] = port_of_wire.emplace(wire_topic(d, port), port);
      if (fresh) continue;
      const std::string& given = d.topics.count(port) ? port : it->second;
      const std::string& other = given == port ? it->second : port;
      if (d.topics.count(other)) {                               // "/x" and "x" are one topic
        if (d.topics.at(given) == d.topics.at(other)) continue;  // the same text: said above
        problems.value({"topics", given}, "topics: \"" + given + "\" and \"" + other +
                                              "\" are both on topic " + it->first +
                                              "; give each port its own topic");
        problems.note_value({"topics", other}, "the topic of \"" + other + "\"");
      } else {
        problems.value({"topics", given}, "topics: \"" + given + "\" is on topic " + it->first +
                                              ", the default topic of " + other + "; give " +
                                              other + " a topic of its own in \"topics\", or " +
                                              given + " another");
      }
    }
  }
  for (const auto& [port, qos] : d.port_qos) {
    if (!app.find_port(port))
      problems.key({"qos", "ports", port}, "qos: ports: \"" + port + "\" is not a port of app " +
                                               app.name + did_you_mean(port, all_ports) +
                                               " (write Module.port as in the spec)");
  }
  check_status_topics(d, app, problems);
  std::set<std::string> known(std::begin(kBuiltinTypes), std::end(kBuiltinTypes));
  for (const model::NamedType& t : app.types) known.insert(t.name);
  // Each message's definition: its .msg file on the message path, else a built-in one.
  ros2::MsgLibrary library(ros2::message_path(d.msg_path), ros2::known_message_texts());
  for (const auto& [name, wire] : d.types) {
    TypePtr type = name == "vec3" ? Type::scalar(Type::Kind::Vec3) : nullptr;
    for (const model::NamedType& t : app.types) {
      if (t.name == name) type = t.type;
    }
    if (type) {
      std::string layout = layout_problem(name, *type, wire, library);
      if (!layout.empty()) problems.value({"types", name}, "types: \"" + name + "\": " + layout);
    }
    if (!known.count(name)) {
      std::string names;
      for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
      problems.key({"types", name}, "types: \"" + name + "\" is not a type of app " + app.name +
                                        did_you_mean(name, {known.begin(), known.end()}) +
                                        " (the types are: " + names + ")");
    }
  }
  return problems.finish();
}

std::string deployment_errors_text(const std::vector<Diagnostic>& errors) {
  std::string out;
  for (const Diagnostic& e : errors) {
    if (!out.empty()) out += '\n';
    out += e.loc.file.str();
    if (e.loc.line > 0)
      out += ":" + std::to_string(e.loc.line) + ":" + std::to_string(e.loc.column);
    out += ": " + e.message;
  }
  return out;
}

std::string wire_topic(const Deployment& d, const std::string& qualified) {
  std::string written;
  auto it = d.topics.find(qualified);
  if (it != d.topics.end()) {
    written = it->second;
  } else {
    written = qualified;
    written[written.find('.')] = '/';
  }
  if (!written.empty() && written.front() == '/') written.erase(0, 1);
  return d.ros2 ? "rt/" + written : written;
}

}  // namespace arbc::dds
