#include "compiler/codegen/yarp_deployment.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace arbc::codegen {

namespace {

// Checks one "Module.port": "/name" entry against the app and the names taken so far.
bool check_entry(const std::string& port, const nlohmann::json& value, const model::App& app,
                 std::map<std::string, std::string>& taken, std::string* err) {
  if (!app.find_port(port)) {
    *err = "\"topics\": \"" + port + "\" is not a port of app '" + app.name +
           "' (write Module.port, as in the spec)";
    return false;
  }
  if (!value.is_string()) {
    *err = "\"topics\": the name of " + port + " must be a string such as \"/robot/" + port + "\"";
    return false;
  }
  std::string name = value.get<std::string>();
  if (name.size() < 2 || name[0] != '/' || name.find_first_of(" \t\r\n") != std::string::npos) {
    *err = "\"topics\": \"" + name + "\" (for " + port +
           ") is not a YARP port name: start it with '/' and use no blanks";
    return false;
  }
  auto [it, fresh] = taken.emplace(name, port);
  if (!fresh) {
    *err = "\"topics\": " + it->second + " and " + port + " are both named \"" + name +
           "\"; give each port its own name";
    return false;
  }
  return true;
}

}  // namespace

std::optional<std::map<std::string, std::string>> read_yarp_deployment(const std::string& path,
                                                                       const model::App& app,
                                                                       std::string* err) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *err = path + ": cannot read the deployment file";
    return std::nullopt;
  }
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    *err = path + ": not a JSON object (docs/yarp.md#names-on-yarp shows the format)";
    return std::nullopt;
  }
  std::map<std::string, std::string> out, taken;
  if (!j.contains("topics")) return out;
  if (!j["topics"].is_object()) {
    *err = path + ": \"topics\" must be an object {\"Module.port\": \"/name\", ...}";
    return std::nullopt;
  }
  for (const auto& [port, value] : j["topics"].items()) {
    std::string why;
    if (!check_entry(port, value, app, taken, &why)) {
      *err = path + ": " + why;
      return std::nullopt;
    }
    out[port] = value.get<std::string>();
  }
  return out;
}

}  // namespace arbc::codegen
