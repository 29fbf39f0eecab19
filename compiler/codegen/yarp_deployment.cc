#include "compiler/codegen/yarp_deployment.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/json_diagnostic.h"
#include "core/suggest.h"

namespace arbc::codegen {

namespace {

// The keys of a deployment file (docs/distributed.md#the-deployment-file): the yarp target
// reads "topics"; the others are the DDS transport's, allowed so that one file serves both.
const std::vector<std::string> kDeploymentKeys = {"domain", "ros2", "topics", "types", "qos"};

// "; did you mean \"x\"?" when one of `candidates` is a plausible typo of `name`, else "".
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  std::optional<std::string> meant = closest_name(name, candidates);
  return meant ? "; did you mean \"" + *meant + "\"?" : "";
}

// The problems of the "topics" entries, each at the key or value it is about.
class Entries {
 public:
  Entries(const std::string& path, std::string_view text, const model::App& app,
          std::vector<Diagnostic>* errors)
      : path_(path), text_(text), app_(app), errors_(errors) {}

  // Checks one "Module.port": "/name" entry against the app and the names taken so far.
  bool check(const std::string& port, const nlohmann::json& value) {
    if (!app_.find_port(port)) {
      std::vector<std::string> ports;
      for (const model::Module& m : app_.modules) {
        for (const model::Port& p : m.ports) ports.push_back(m.name + "." + p.name);
      }
      error({"topics", port}, JsonPart::Key,
            "\"topics\": \"" + port + "\" is not a port of app '" + app_.name + "'" +
                did_you_mean(port, ports) + " (write Module.port, as in the spec)");
      return false;
    }
    if (!value.is_string()) {
      error(
          {"topics", port}, JsonPart::Value,
          "\"topics\": the name of " + port + " must be a string such as \"/robot/" + port + "\"");
      return false;
    }
    std::string name = value.get<std::string>();
    if (name.size() < 2 || name[0] != '/' || name.find_first_of(" \t\r\n") != std::string::npos) {
      error({"topics", port}, JsonPart::Value,
            "\"topics\": \"" + name + "\" (for " + port +
                ") is not a YARP port name: start it with '/' and use no blanks");
      return false;
    }
    auto [it, fresh] = taken_.emplace(name, port);
    if (!fresh) {
      // At the later of the two in the file (the library hands the keys over sorted), with a
      // note at the other.
      std::string first = it->second, second = port;
      if (before(second, first)) std::swap(first, second);
      error({"topics", second}, JsonPart::Value,
            "\"topics\": " + first + " and " + second + " are both named \"" + name +
                "\"; give each port its own name");
      errors_->back().notes.push_back(json_diagnostic(path_, text_, {"topics", first},
                                                      JsonPart::Value, "the name of " + first));
      errors_->back().notes.back().severity = Severity::Note;
      return false;
    }
    return true;
  }

  // Whether the entry of port a comes before that of port b in the file.
  bool before(const std::string& a, const std::string& b) const {
    std::optional<TextSpan> x = json_place(text_, {"topics", a}, JsonPart::Key);
    std::optional<TextSpan> y = json_place(text_, {"topics", b}, JsonPart::Key);
    if (!x || !y) return false;
    return std::pair(x->begin.line, x->begin.column) < std::pair(y->begin.line, y->begin.column);
  }

  void error(const std::vector<std::string>& where, JsonPart part, std::string message) {
    errors_->push_back(json_diagnostic(path_, text_, where, part, std::move(message)));
  }

 private:
  const std::string& path_;
  std::string_view text_;
  const model::App& app_;
  std::vector<Diagnostic>* errors_;
  std::map<std::string, std::string> taken_;  // YARP name -> port
};

}  // namespace

std::optional<std::map<std::string, std::string>> read_yarp_deployment(
    const std::string& path, const model::App& app, std::vector<Diagnostic>* errors) {
  std::error_code ec;
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path, ec)) {
    Diagnostic d;
    d.loc.file = path;
    d.message = std::string("cannot read the deployment file") +
                (std::filesystem::is_directory(path, ec) ? " (it is a directory)"
                 : std::filesystem::exists(path, ec)     ? " (permission denied?)"
                                                         : " (no such file)") +
                "; --deploy takes a JSON file such as {\"topics\": {\"Module.port\": "
                "\"/yarp/name\"}} (docs/yarp.md#deploying-a-spec-on-yarp-step-by-step)";
    errors->push_back(std::move(d));
    return std::nullopt;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  nlohmann::json j;
  if (JsonParseError e; !parse_json(text, &j, &e)) {
    errors->push_back(json_syntax_diagnostic(path, e));
    return std::nullopt;
  }
  Entries entries(path, text, app, errors);
  if (!j.is_object()) {
    entries.error({}, JsonPart::Value,
                  "not a JSON object (docs/yarp.md#names-on-yarp shows the format)");
    return std::nullopt;
  }
  // A key the file format does not have is most likely a misspelt "topics", which would
  // otherwise leave every port with its default name without a word.
  size_t first_key_error = errors->size();
  for (const auto& [key, value] : j.items()) {
    if (std::find(kDeploymentKeys.begin(), kDeploymentKeys.end(), key) != kDeploymentKeys.end())
      continue;
    entries.error({key}, JsonPart::Key,
                  "unknown key \"" + key + "\"" + did_you_mean(key, kDeploymentKeys) +
                      " (the keys are: domain, ros2, topics, types, qos; the yarp target reads "
                      "\"topics\", the others are the DDS transport's)");
  }
  if (errors->size() != first_key_error) return std::nullopt;
  std::map<std::string, std::string> out;
  if (!j.contains("topics")) return out;
  if (!j["topics"].is_object()) {
    entries.error({"topics"}, JsonPart::Value,
                  "\"topics\" must be an object {\"Module.port\": \"/name\", ...}");
    return std::nullopt;
  }
  size_t first = errors->size();
  for (const auto& [port, value] : j["topics"].items()) {
    if (entries.check(port, value)) out[port] = value.get<std::string>();
  }
  if (errors->size() == first) return out;
  // The library hands the keys over sorted: report in the file's order.
  std::stable_sort(errors->begin() + static_cast<std::ptrdiff_t>(first), errors->end(),
                   [](const Diagnostic& a, const Diagnostic& b) {
                     return std::pair(a.loc.line, a.loc.column) <
                            std::pair(b.loc.line, b.loc.column);
                   });
  return std::nullopt;
}

}  // namespace arbc::codegen
