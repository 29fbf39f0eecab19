// A stand-in for YARP's Lua bindings (`require("yarp")`), enough for what monitor scripts
// commonly call at load time, in `create`, and in `accept` on sample bottles: yarp.Bottle,
// yarp.Value, yarp.Property, yarp.Vector, yarp.now / yarp.Time_now / yarp.Time_delay, and the
// `thing:asBottle()` of a callback's argument. Anything else raises an error that names it
// (docs/yarp.md#how-arbc-reads-a-monitor). Plain Lua, kept in yarp_stand_in.lua and compiled
// in (arbc_embed_text), run in the script's sandbox.
#pragma once

#include <string_view>

namespace arbc::yarp {

// Defines the globals `yarp`, `require` (which knows only "yarp") and the helper
// `__arbc_thing(text)` that makes a callback argument whose asBottle() parses `text`.
std::string_view yarp_stand_in_source();

}  // namespace arbc::yarp
