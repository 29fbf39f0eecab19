// The sandbox's bounded versions of the Lua library functions whose work one C call can make
// unbounded, where the instruction hook never fires (docs/reliability.md, "A stuck monitor"):
//
//   string.find, string.match, string.gmatch, string.gsub  our matcher (lua_pattern.h), every
//                       step charged to the callback's library budget; plain searches (string.find
//                       with plain = true, or a pattern without special characters) in linear
//                       time, where Lua's own is quadratic
//   string.rep          an empty result without Lua's loop of n empty copies
//   table.move          the number of elements charged before Lua's own move runs
//
// Each stops with the budget's error when LuaSandbox::charge says so. Same arguments, results
// and error texts as Lua 5.4's, which `s:find(...)` reaches too (strings index the string table).
#pragma once

struct lua_State;

namespace arbc {

// Replaces the functions above in the state's string and table libraries (opened already).
// Runs inside a protected call (it may raise a memory error).
void install_bounded_library(lua_State* L);

}  // namespace arbc
