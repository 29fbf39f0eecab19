// Locks (docs/language.md#locks): `event estop = lock EStop.engaged [: PRED] [timeout D];` is
// engaged while its last message says so (PRED, or the message itself for a `bool` port, or its
// `data` field for std_msgs/msg/Bool), and fails closed: also before its publisher first speaks
// and, with `timeout D`, once it has been silent for D; `otherwise open after D` instead lets
// silence since the start open it. No new construct reaches sema, the proof, the generated Lua
// or the runtime: the lock is written as the two derived events a user would write by hand
// (docs/language.md#a-stop-that-must-act-at-once), and its name as their meaning:
//   event estop_engaged = EStop.engaged : PRED;             // a message with PRED false unsets it
//   event estop_heard   = EStop.engaged : true [for D];     // absent until the publisher speaks
//   `estop` in a constraint              ->  (estop_engaged or not estop_heard)
//   `never R while estop;`               ->  `never R while estop_engaged;` and
//                                            `assert PORT: R -> estop_heard;` (PORT: R's port)
// With `otherwise open after D` there is no heard event: `estop` is `estop_engaged`, declared
// `otherwise absent after D`. A lock where one event is needed (a response's trigger, an
// exclusive group, an assumption) is an error (`lock`).
#pragma once

#include <vector>

#include "compiler/frontend/ast.h"
#include "core/diagnostic.h"

namespace arbc::frontend {

void desugar_locks(ast::Spec& spec, std::vector<Diagnostic>& out);

}  // namespace arbc::frontend
