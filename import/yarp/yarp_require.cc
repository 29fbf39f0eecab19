#include "import/yarp/yarp_require.h"

#include <cctype>
#include <string>
#include <string_view>

#include "import/yarp/app_xml.h"

namespace arbc::yarp {

namespace {

// The callbacks to which YARP passes a SWIG object (MonitorLua.cpp: SWIG_TypeQuery), in the
// order YARP first calls them.
const char* const kCallbacksWithYarpObjects[] = {"create",       "accept",   "update",
                                                 "update_reply", "setparam", "getparam"};

// The line that defines PortMonitor.<callback> (the first that names it), else 1.
int definition_line(const std::string& text, const std::string& callback) {
  std::string name = "PortMonitor." + callback;
  int line = 1;
  for (size_t start = 0; start < text.size(); ++line) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view l(text.data() + start, end - start);
    size_t at = l.find(name);
    if (at != std::string_view::npos && l.find("--") > at) {
      size_t after = at + name.size();
      if (after == l.size() ||
          !(std::isalnum(static_cast<unsigned char>(l[after])) || l[after] == '_'))
        return line;
    }
    start = end + 1;
  }
  return 1;
}

}  // namespace

void check_requires_yarp(const ImportedConnection& ic, std::vector<Diagnostic>& out) {
  if (!ic.monitor || !ic.monitor->run.loaded || ic.monitor->run.requires_yarp) return;
  const MonitorAnalysis& m = *ic.monitor;
  const char* first = nullptr;
  for (const char* callback : kCallbacksWithYarpObjects) {
    if (m.facts.callbacks.count(callback)) {
      first = callback;
      break;
    }
  }
  if (!first) return;  // trig and destroy get no argument: YARP does not need the bindings
  Diagnostic d;
  d.severity = Severity::Error;
  d.loc = ic.xml.protocol_loc;
  d.id = kIdRequire;
  std::string callback = first;
  std::string when = callback == "create" ? "as the connection is made" : "at the first message";
  d.message = "the monitor " + m.path + " of " + ic.xml.from + " -> " + ic.xml.to +
              " does not require(\"yarp\") when it loads: the process that opens " + ic.xml.to +
              " crashes " + when;
  Diagnostic here;
  here.severity = Severity::Note;
  std::string defined = "PortMonitor." + callback;
  here.loc = locate(m.path, m.text, definition_line(m.text, callback), defined);
  here.message = "YARP calls " + defined +
                 " with a YARP object, whose Lua type exists only once YARP's Lua bindings are "
                 "loaded";
  d.notes.push_back(std::move(here));
  Diagnostic fix;
  fix.severity = Severity::Note;
  fix.message = "make require(\"yarp\") the script's first line";
  d.notes.push_back(std::move(fix));
  out.push_back(std::move(d));
}

}  // namespace arbc::yarp
