#include "import/twist_mux/twist_mux_config.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/check_ids.h"

namespace arbc::twist_mux {
namespace {

constexpr const char* kShape =
    "twist_mux reads `topics:` and `locks:`: in ROS 2 `NODE: ros__parameters: topics: NAME: "
    "{topic: T, timeout: S, priority: P}`, in ROS 1 a list of `{name, topic, timeout, priority}`";

// Reads one file's entries; errors and warnings go to `out.diagnostics`.
class Reader {
 public:
  Reader(std::string file, MuxConfig& out) : file_(std::move(file)), out_(out) {}

  void read(const YAML::Node& root) {
    if (!root.IsMap()) return error(root, std::string("not a twist_mux parameter file: ") + kShape);
    if (root["topics"] || root["locks"]) return read_lists(root);  // ROS 1
    bool any = false;
    for (const auto& node : root) {
      const YAML::Node params = node.second.IsMap() ? node.second["ros__parameters"] : YAML::Node();
      if (!params || !params.IsMap()) continue;
      any = true;
      read_maps(params);
    }
    if (!any) error(root, std::string("not a twist_mux parameter file: ") + kShape);
  }

 private:
  model::SourceLocation loc(const YAML::Node& n) const {
    model::SourceLocation l;
    l.file = file_;
    l.line = n.Mark().line + 1;
    l.column = n.Mark().column + 1;
    return l;
  }
  void error(const YAML::Node& n, std::string message) {
    out_.diagnostics.push_back(
        make_diagnostic(Severity::Error, loc(n), std::move(message), diag::TwistMux.text()));
  }
  void warning(const YAML::Node& n, std::string message) {
    out_.diagnostics.push_back(make_diagnostic(Severity::Warning, loc(n), std::move(message),
                                               diag::TwistMuxChoice.text()));
  }

  // ROS 2: `topics:` and `locks:` map names to entries.
  void read_maps(const YAML::Node& params) {
    for (const char* kind : {"topics", "locks"}) {
      const YAML::Node group = params[kind];
      if (!group) continue;
      if (!group.IsMap())
        return error(group, std::string("`") + kind + ":` under ros__parameters maps each name " +
                                "to {topic, timeout, priority}");
      for (const auto& item : group) entry(item.first, item.second, kind);
    }
  }
  // ROS 1: `topics:` and `locks:` are lists whose entries carry their `name:`.
  void read_lists(const YAML::Node& root) {
    for (const char* kind : {"topics", "locks"}) {
      const YAML::Node group = root[kind];
      if (!group || group.IsNull()) continue;
      if (!group.IsSequence())
        return error(group, std::string("`") + kind + ":` is a list of {name, topic, timeout, " +
                                "priority} (ROS 1), or lives under `NODE: ros__parameters:` " +
                                "(ROS 2)");
      for (const YAML::Node& item : group) {
        if (!item.IsMap() || !item["name"])
          return error(item, std::string("each entry of `") + kind + ":` needs a `name:`");
        entry(item["name"], item, kind);
      }
    }
  }

  std::optional<std::string> text(const YAML::Node& entry, const char* key,
                                  const std::string& who) {
    const YAML::Node v = entry[key];
    if (!v || !v.IsScalar() || v.Scalar().empty()) {
      error(v ? v : entry, who + " needs `" + key + ":`, a name");
      return std::nullopt;
    }
    return v.Scalar();
  }
  std::optional<double> number(const YAML::Node& entry, const char* key, const std::string& who) {
    const YAML::Node v = entry[key];
    double d = 0;
    if (!v || !v.IsScalar() || !YAML::convert<double>::decode(v, d)) {
      error(v ? v : entry, who + " needs `" + key + ":`, a number");
      return std::nullopt;
    }
    return d;
  }

  void entry(const YAML::Node& name_node, const YAML::Node& e, const std::string& kind) {
    bool lock = kind == "locks";
    std::string who = std::string(lock ? "lock" : "input") + " '" + name_node.Scalar() + "'";
    if (!e.IsMap()) return error(e, who + " is {topic, timeout, priority}");
    std::optional<std::string> topic = text(e, "topic", who);
    std::optional<double> timeout = number(e, "timeout", who);
    std::optional<double> priority = number(e, "priority", who);
    if (!topic || !timeout || !priority) return;
    MuxEntry m{name_node.Scalar(), *topic, *timeout, 0, lock, loc(name_node), loc(e["priority"])};
    if (*priority != static_cast<double>(static_cast<long long>(*priority)))
      return error(e["priority"], who + ": a priority is a whole number in 0..255");
    long long p = static_cast<long long>(*priority);
    m.priority = static_cast<int>(std::clamp(p, 0LL, 255LL));
    if (p != m.priority)
      warning(e["priority"], who + ": twist_mux clamps priorities to 0..255, so " +
                                 std::to_string(p) + " is taken as " + std::to_string(m.priority));
    if (m.timeout < 0) {
      warning(e["timeout"], who + ": twist_mux takes a timeout of 0 or below as none (the " +
                                (lock ? "lock" : "input") + " never expires); write 0");
      m.timeout = 0;
    }
    std::vector<MuxEntry>& into = lock ? out_.locks : out_.inputs;
    for (const MuxEntry& other : into) {
      if (other.name == m.name)
        return error(name_node, who + " is named twice (also at " + std::string(other.loc.file) +
                                    ":" + std::to_string(other.loc.line) +
                                    "); twist_mux keeps one entry per name");
    }
    into.push_back(std::move(m));
  }

  std::string file_;
  MuxConfig& out_;
};

// A topic twist_mux subscribes to twice, once as an input and once as a lock: one program
// cannot publish a Twist and a Bool on one topic.
void topics_of_two_types(MuxConfig& c) {
  for (const MuxEntry& l : c.locks) {
    for (const MuxEntry& i : c.inputs) {
      if (i.topic != l.topic) continue;
      c.diagnostics.push_back(make_diagnostic(
          Severity::Error, l.loc,
          "lock '" + l.name + "' reads topic " + l.topic + ", which input '" + i.name + "' (line " +
              std::to_string(i.loc.line) +
              ") reads too: an input carries geometry_msgs/msg/Twist, a lock std_msgs/msg/Bool; "
              "give the lock a topic of its own",
          diag::TwistMux.text()));
    }
  }
}

}  // namespace

void read_twist_mux_text(const std::string& text, const std::string& file, MuxConfig& into) {
  try {
    Reader(file, into).read(YAML::Load(text));
  } catch (const YAML::Exception& e) {
    model::SourceLocation l;
    l.file = file;
    l.line = e.mark.line + 1;
    l.column = e.mark.column + 1;
    into.diagnostics.push_back(
        make_diagnostic(Severity::Error, l, "not YAML: " + e.msg, diag::TwistMux.text()));
  }
}

MuxConfig read_twist_mux(const std::vector<std::string>& files) {
  MuxConfig c;
  for (const std::string& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      model::SourceLocation l;
      l.file = f;
      c.diagnostics.push_back(
          make_diagnostic(Severity::Error, l, "cannot read the file", diag::TwistMux.text()));
      continue;
    }
    std::stringstream s;
    s << in.rdbuf();
    read_twist_mux_text(s.str(), f, c);
  }
  topics_of_two_types(c);
  bool errors = false;
  for (const Diagnostic& d : c.diagnostics) errors = errors || d.severity == Severity::Error;
  if (!errors && c.inputs.empty()) {
    model::SourceLocation l;
    l.file = files.empty() ? "" : files.front();
    l.line = 1;
    c.diagnostics.push_back(make_diagnostic(
        Severity::Error, l, "no input: twist_mux needs at least one entry under `topics:`",
        diag::TwistMux.text()));
    errors = true;
  }
  c.ok = !errors;
  return c;
}

}  // namespace arbc::twist_mux
