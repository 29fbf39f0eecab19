// One YARP connection's Lua monitor (docs/yarp.md#how-the-monitors-are-written): the spec's
// connections that share the (source, destination) pair, each as the embedded target writes
// it but with its callbacks in a private table, YARP event names and explicit lifetimes; around
// them, callbacks written against YARP's Lua API that convert Bottles, run each part under
// pcall (every callback is total), drive `every` from timestamps, enforce the throttle, set a
// `by priority` rule's activity event as it delivers, and unset the monitor's events in destroy.
#pragma once

#include <string>
#include <vector>

#include "compiler/codegen/monitor_writer.h"
#include "compiler/codegen/yarp_names.h"
#include "compiler/lower/lowered_app.h"
#include "core/diagnostic.h"

namespace arbc::codegen {

// The monitor of `link`; a part YARP cannot run (a `script` rule, two rules on one pair) is
// reported in `diags` and the text is then not usable. Bodies never read events (the IR has no
// such node: the checker keeps events to constraints), which YARP's Lua API could not do.
std::string write_yarp_monitor(const lower::LoweredApp& app, const YarpLink& link,
                               const YarpNames& names, const SpecLines& lines,
                               std::vector<Diagnostic>& diags);

}  // namespace arbc::codegen
