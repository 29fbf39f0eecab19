// What arbc learns about a YARP port monitor script from its text, without running it
// (docs/yarp.md#how-arbc-reads-a-monitor):
//   - every PortMonitor.setEvent / unsetEvent / setConstraint / setTrigInterval call, with its
//     line and literal arguments;
//   - the events `accept` sets (or unsets) on every path on which it accepts (must-set and
//     must-unset: the effective guard of docs/design.md#effective-guards);
//   - pairs of events the script never leaves both set, on any path of any callback (a selector
//     that sets one and unsets the other), which make an exclusive group when no other monitor
//     sets either.
// Anything the analysis cannot follow makes the script opaque (names) or drops the path facts
// (fewer facts weaken the proof, never make it unsound).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "import/yarp/lua_ast.h"

namespace arbc::yarp {

// One call of a PortMonitor function in the script.
struct MonitorCall {
  std::string function;             // "setEvent", "unsetEvent", "setConstraint", "setTrigInterval"
  std::optional<std::string> text;  // the first argument when it is a string literal
  std::optional<double> number;     // setEvent's lifetime / setTrigInterval's argument, if known
  bool has_second = false;          // setEvent was given a lifetime argument
  int line = 0;
  std::string callback;           // "accept", "trig", ...; "" at load time; "(helper)" elsewhere
  const LuaExpr* node = nullptr;  // the call in the tree the facts were taken from
};

struct ScriptFacts {
  std::vector<MonitorCall> calls;   // in source order
  std::set<std::string> callbacks;  // PortMonitor.<name> defined as functions
  // Event names not all known: a computed name, or PortMonitor used other than as `PortMonitor.f`.
  bool opaque = false;
  std::string opaque_reason;
  int opaque_line = 0;
  std::string opaque_token;  // the text at opaque_line to point at
  // Opaque only because some setEvent/unsetEvent names are computed: the callbacks are still
  // the script's own, so what `accept` returns is known (accept_may_accept), and a status
  // monitor that sets computed events and returns false (the paper's C3) is still a feed.
  bool opaque_names_only = false;

  // Path facts; valid only when paths_ok (else why not, in paths_reason).
  bool paths_ok = false;
  std::string paths_reason;
  // Some path of accept returns a true value (or no accept). Valid when paths_ok, and also
  // when the script is opaque_names_only.
  bool accept_may_accept = true;
  std::set<std::string> must_set, must_unset;                   // on every accepting path of accept
  std::vector<std::pair<std::string, std::string>> never_both;  // sorted pairs
  // Events `update` sets with a known positive lifetime on every path, and nothing but update
  // sets or unsets (destroy may unset them): YARP runs update on what is delivered, so such an
  // event is a `by priority` activity event, set as the connection delivers
  // (docs/design.md#priorities-and-holds).
  std::set<std::string> delivery_set;

  std::set<std::string> sets() const;    // literal names passed to setEvent
  std::set<std::string> unsets() const;  // literal names passed to unsetEvent
};

// Lexical facts (calls, callbacks, opaque), then the path facts.
ScriptFacts analyse_script(const LuaFunction& chunk);

// The path facts of `facts` (fills paths_ok .. never_both). Called by analyse_script.
void analyse_paths(const LuaFunction& chunk, ScriptFacts& facts);

// The function assigned to PortMonitor.<name> at the top level of the chunk, or nullptr.
const LuaFunction* find_callback(const LuaFunction& chunk, const std::string& name);

}  // namespace arbc::yarp
