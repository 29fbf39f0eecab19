#include "harness/run_inputs.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/duration_parse.h"
#include "core/json_parse.h"
#include "core/json_place.h"
#include "core/time_text.h"
#include "core/value_json.h"
#include "harness/out_port_hint.h"
#include "runtime/trace_format.h"

namespace arbc::harness {

namespace {

using Json = nlohmann::json;

// One line's place, for errors: "inputs.jsonl:3: ", or "inputs.jsonl:3:17: " at a field's
// value (or at a column), as compilers place theirs, so that an editor jumps to it.
struct LineRef {
  const std::string& path;
  size_t line;
  const std::string& text;  // the line
  std::string operator()(const std::string& what, int column = 0) const {
    std::string where = path + ":" + std::to_string(line);
    if (column > 0) where += ":" + std::to_string(column);
    return where + ": " + what;
  }
  // About the value of `field` (at the line alone when the line has no such field).
  std::string field(const std::string& field, const std::string& what) const {
    std::optional<TextSpan> span = json_place(text, {field});
    return (*this)("field '" + field + "': " + what, span ? span->begin.column : 0);
  }
};

// What is wrong with a line's `t`, or "". A newcomer writes times as the spec does ("100ms"):
// the message says what to write instead.
std::string bad_time(const Json& j) {
  const char* want = "the time in seconds from the start, a number >= 0 such as 0.5";
  if (!j.contains("t")) return std::string("missing: ") + want;
  const Json& t = j["t"];
  if (t.is_string()) {
    std::string text = t.get<std::string>(), why;
    double seconds = 0;
    if (parse_duration(text, BareNumber::Refused, true, &seconds, &why))
      return "\"" + text + "\" is a string; write " + time_text(seconds) + ", the time in seconds";
    return "\"" + text + "\" is a string; write " + want;
  }
  if (!t.is_number()) return std::string("not a number; write ") + want;
  if (t.get<double>() < 0) return "negative; write " + std::string(want);
  return "";
}

// The input a line holds, appended to *log. `skip` is set for a trace line that is not a
// publication, or one by a module a plugin provides.
bool read_line(const Json& j, const LineRef& at, const model::App& app,
               const std::vector<std::string>& stand_ins, StandInLog* log, InputsRead* read,
               std::string* err) {
  if (!j.is_object()) return *err = at("not a JSON object"), false;
  bool trace_line = j.contains("type");
  if (trace_line) {
    read->from_trace = true;
    if (!j["type"].is_string() ||
        trace_kind_named(j["type"].get<std::string>()) != TraceKind::Publish)
      return true;  // what the run did, not what the modules published
  }
  if (std::string why = bad_time(j); !why.empty()) return *err = at.field("t", why), false;
  if (!j.contains("port") || !j["port"].is_string())
    return *err = at.field("port", "a \"Module.port\" string is required"), false;
  std::string port = j["port"];
  const model::Port* p = app.find_port(port);
  if (!p || p->direction != model::Direction::Out)
    return *err = at.field("port", not_an_out_port(app, port)), false;
  std::string module = port.substr(0, port.find('.'));
  if (std::find(stand_ins.begin(), stand_ins.end(), module) == stand_ins.end()) {
    if (trace_line) return ++read->skipped_provided, true;  // the plugin publishes anew
    return *err = at.field("port", "module " + module +
                                       " is provided by a plugin, which publishes on its ports "
                                       "itself"),
           false;
  }
  if (!j.contains("value")) return *err = at.field("value", "missing"), false;
  std::string why;
  std::optional<Value> v = value_from_json(j["value"], *p->type, &why);
  if (!v)
    return *err = at.field("value", why + " (port " + port + " is " + p->type->to_string() + ")"),
           false;
  // To the nearest nanosecond, the runtime's instants (core/instant.h): a trace's times, which
  // it writes exactly, read back as the instants they were.
  log->add_input({nanos_from_seconds(j["t"].get<double>()), port, std::move(*v)});
  ++read->messages;
  return true;
}

}  // namespace

bool read_inputs(const std::string& path, const model::App& app,
                 const std::vector<std::string>& stand_ins, StandInLog* log, InputsRead* read,
                 std::string* err) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))  // an ifstream opens it and reads nothing
    return *err = path + ": a directory; --inputs takes a file of JSON lines (or a trace)", false;
  std::ifstream in(path);
  if (!in) return *err = path + ": cannot read the inputs file: " + std::strerror(errno), false;
  std::string text;
  for (size_t line = 1; std::getline(in, text); ++line) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    LineRef at{path, line, text};
    Json j;
    if (JsonParseError e; !parse_json(text, &j, &e)) {
      if (e.first_line)  // a key repeated: each line is parsed alone, so the place is a column
        return *err = at(json_error_message(e, /*one_line=*/true), e.column), false;
      return *err = at("not valid JSON: " + e.detail, e.column), false;
    }
    if (!read_line(j, at, app, stand_ins, log, read, err)) return false;
  }
  return true;
}

}  // namespace arbc::harness
