// The spec language's builtins (core/builtins.h: each row names its `lua_helper` here) as plain
// Lua 5.4 local functions, copied into each generated monitor that uses them, so every monitor
// is a self-contained file that needs nothing but the PortMonitor API
// (docs/runtime.md#lua-monitors-the-portmonitor-api).
//
// "No value" (min_by of an empty list, an index out of range) calls PortMonitor.novalue(),
// which ends the callback; the runtime drops the message with the reason "no-value", counted
// and traced, not a script error (docs/runtime.md).
#pragma once

#include <set>
#include <string>
#include <string_view>

namespace arbc::codegen {

// Helper names, usable in `used` below. Builtins keep their spec names; helpers the generated
// code needs internally start with "arbc_".
inline constexpr std::string_view kNoValueHelper = "arbc_no_value";
inline constexpr std::string_view kIndexHelper = "arbc_index";

// True for the helper names of the builtins (core/builtins.h's `lua_helper`).
bool is_builtin(std::string_view name);

// Names a spec variable must not take in generated Lua: builtins, Lua's standard globals the
// generated code calls, PortMonitor, and anything starting with "arbc_".
bool is_reserved_lua_name(std::string_view name);

// `used` plus every helper they call.
std::set<std::string> helper_closure(const std::set<std::string>& used);

// Lua source defining the helpers in `used` (and what they depend on), in a fixed order, each
// opened by a one-line comment. Empty when `used` is empty.
std::string lua_prelude(const std::set<std::string>& used);

}  // namespace arbc::codegen
