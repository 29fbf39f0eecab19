// A YARP carrier string, as the portmonitor carrier reads it (Protocol::getSenderSpecifier in
// libYARP_os, then PortMonitor::configureFromProperty):
//   tcp+recv.portmonitor+type.lua+file.NAME[+context.CTX][+constraint.WORD]
// Each `+`-separated modifier is `key.value`; YARP turns every `.` into a space, so a value
// holds no dot (a file `NAME` means `NAME` or `NAME.lua`) and a constraint given here is one
// word. Without `recv.portmonitor` the connection has no receiving-side monitor.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace arbc::yarp {

struct Carrier {
  std::string base = "tcp";   // the carrier before the first '+'
  bool monitor = false;       // recv.portmonitor: a monitor in the receiving process
  bool send_monitor = false;  // send.portmonitor: in the sending process (never arbitrates)
  std::string type = "lua";   // type.<lua|dll>
  std::string file;           // file.NAME (YARP's default: "modifier")
  std::string context;        // context.CTX
  std::optional<std::string> constraint;                       // constraint.WORD
  std::vector<std::pair<std::string, std::string>> modifiers;  // all, as YARP reads them
};

// Parses `text` (empty means plain tcp). Returns false and sets *err when a modifier has a
// value YARP would split into several words (a dot inside it) or no key.
bool parse_carrier(std::string_view text, Carrier* out, std::string* err);

}  // namespace arbc::yarp
