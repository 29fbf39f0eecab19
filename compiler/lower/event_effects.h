// Which events a monitor body sets and unsets: on some path (`sets`, `unsets`: for the
// verifier's `unused`, `unfed` and `ownership` checks) and on every path on which the message is
// accepted (`must_set`, `must_unset`: docs/design.md#effective-guards).
//
// The analysis is an under-approximation of the "every path" sets, which keeps the proof sound:
// fewer must-events make a rule's effective guard weaker, so the verifier may report an overlap
// that cannot happen, never miss one that can.
#pragma once

#include <set>
#include <string>

#include "compiler/frontend/ast.h"

namespace arbc::lower {

struct EventEffects {
  std::set<std::string> sets, unsets;
  std::set<std::string> must_set, must_unset;
};

// Effects of `body` when it runs on a message. `every` blocks run from trig(), not per
// message: they count for sets/unsets only.
EventEffects body_effects(const ast::Block& body);

// Event names passed as string literals to PortMonitor.setEvent / unsetEvent in a hand-written
// script, so that the verifier knows what an opaque `script` rule can feed.
EventEffects script_effects(const std::string& script_text);

}  // namespace arbc::lower
