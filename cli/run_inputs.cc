#include "cli/run_inputs.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/json_parse.h"
#include "core/value_json.h"

namespace arbc::cli {

namespace {

using Json = nlohmann::json;

// One line's place, for errors: "inputs.jsonl:3: ".
struct LineRef {
  const std::string& path;
  size_t line;
  std::string operator()(const std::string& what) const {
    return path + ":" + std::to_string(line) + ": " + what;
  }
};

// The input a line holds, appended to *log. `skip` is set for a trace line that is not a
// publication, or one by a module a plugin provides.
bool read_line(const Json& j, const LineRef& at, const model::App& app,
               const std::vector<std::string>& stand_ins, StandInLog* log, InputsRead* read,
               std::string* err) {
  if (!j.is_object()) return *err = at("not a JSON object"), false;
  bool trace_line = j.contains("type");
  if (trace_line) {
    read->from_trace = true;
    if (!j["type"].is_string() || j["type"] != "publish") return true;  // what the run did
  }
  if (!j.contains("t") || !j["t"].is_number() || j["t"].get<double>() < 0)
    return *err = at("field 't': a time in seconds >= 0 is required"), false;
  if (!j.contains("port") || !j["port"].is_string())
    return *err = at("field 'port': a \"Module.port\" string is required"), false;
  std::string port = j["port"];
  const model::Port* p = app.find_port(port);
  if (!p || p->direction != model::Direction::Out)
    return *err = at("field 'port': '" + port + "' is not an out-port of app " + app.name), false;
  std::string module = port.substr(0, port.find('.'));
  if (std::find(stand_ins.begin(), stand_ins.end(), module) == stand_ins.end()) {
    if (trace_line) return ++read->skipped_provided, true;  // the plugin publishes anew
    return *err = at("field 'port': module " + module +
                     " is provided by a plugin, which publishes on its ports itself"),
           false;
  }
  if (!j.contains("value")) return *err = at("field 'value': missing"), false;
  std::string why;
  std::optional<Value> v = value_from_json(j["value"], *p->type, &why);
  if (!v)
    return *err =
               at("field 'value': " + why + " (port " + port + " is " + p->type->to_string() + ")"),
           false;
  log->inputs[module].push_back({j["t"].get<double>(), port, std::move(*v)});
  ++read->messages;
  return true;
}

}  // namespace

bool read_inputs(const std::string& path, const model::App& app,
                 const std::vector<std::string>& stand_ins, StandInLog* log, InputsRead* read,
                 std::string* err) {
  std::ifstream in(path);
  if (!in) return *err = path + ": cannot read the inputs file", false;
  std::string text;
  for (size_t line = 1; std::getline(in, text); ++line) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    LineRef at{path, line};
    Json j;
    if (JsonParseError e; !parse_json(text, &j, &e)) {
      std::string where = e.column ? " at column " + std::to_string(e.column) : "";
      return *err = at("not valid JSON" + where + ": " + e.detail), false;
    }
    if (!read_line(j, at, app, stand_ins, log, read, err)) return false;
  }
  for (auto& [module, values] : log->inputs) {
    std::stable_sort(values.begin(), values.end(),
                     [](const TimedValue& a, const TimedValue& b) { return a.t < b.t; });
  }
  return true;
}

}  // namespace arbc::cli
