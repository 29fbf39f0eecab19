#include "compiler/codegen/lua_prelude.h"

#include <array>

#include "core/builtins.h"

namespace arbc::codegen {

namespace {

struct Helper {
  std::string_view name;
  std::array<std::string_view, 1> needs;  // the helper this one calls, if any (else empty)
  std::string_view source;
};

// Order matters: a helper comes after the helpers it calls (Lua locals must be defined first).
constexpr Helper kHelpers[] = {
    {"arbc_no_value",
     {},
     "-- An expression without a value ends the callback: the runtime drops the message\n"
     "-- with reason \"no-value\" (docs/runtime.md).\n"
     "local function arbc_no_value() PortMonitor.novalue() end\n"},
    {"arbc_index",
     {"arbc_no_value"},
     "-- xs[i], counting from 0 as the spec does; out of range has no value.\n"
     "local function arbc_index(xs, i)\n"
     "  local x = xs[i + 1]\n"
     "  if x == nil then arbc_no_value() end\n"
     "  return x\n"
     "end\n"},
    {"arbc_fmod",
     {"arbc_no_value"},
     "-- a % b of the spec: C's fmod, truncating (Lua's own % floors); math.fmod raises on an\n"
     "-- int divided by int 0, which has no value instead (docs/language.md#numbers).\n"
     "local function arbc_fmod(a, b)\n"
     "  if b == 0 and math.type(a) == \"integer\" and math.type(b) == \"integer\" then\n"
     "    arbc_no_value()\n"
     "  end\n"
     "  return math.fmod(a, b)\n"
     "end\n"},
    {"len",
     {},
     "-- len(xs): the number of elements of a list, or of bytes of a string.\n"
     "local function len(xs) return #xs end\n"},
    {"arbc_best_by",
     {"arbc_no_value"},
     "-- The first element of xs whose key(x) is best by `better`; none when xs is empty.\n"
     "local function arbc_best_by(xs, key, better)\n"
     "  local best, best_key = nil, nil\n"
     "  for i = 1, #xs do\n"
     "    local k = key(xs[i])\n"
     "    if best == nil or better(k, best_key) then best, best_key = xs[i], k end\n"
     "  end\n"
     "  if best == nil then arbc_no_value() end\n"
     "  return best\n"
     "end\n"},
    {"min_by",
     {"arbc_best_by"},
     "-- min_by(xs, f): the element with the smallest f(x).\n"
     "local function min_by(xs, key) return arbc_best_by(xs, key, function(a, b) return a < b "
     "end) end\n"},
    {"max_by",
     {"arbc_best_by"},
     "-- max_by(xs, f): the element with the largest f(x).\n"
     "local function max_by(xs, key) return arbc_best_by(xs, key, function(a, b) return a > b "
     "end) end\n"},
    {"norm",
     {},
     "-- norm(v): the length of a vec3.\n"
     "local function norm(v) return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z) end\n"},
    {"dist",
     {},
     "-- dist(a, b): the Euclidean distance between two vec3.\n"
     "local function dist(a, b)\n"
     "  local dx, dy, dz = a.x - b.x, a.y - b.y, a.z - b.z\n"
     "  return math.sqrt(dx * dx + dy * dy + dz * dz)\n"
     "end\n"},
    {"abs", {}, "-- abs(x): the absolute value.\nlocal function abs(x) return math.abs(x) end\n"},
    {"min",
     {"arbc_no_value"},
     "-- min(a, b, ...) of numbers, or min(xs) of a list (an empty list has no value).\n"
     "local function min(a, ...)\n"
     "  if select(\"#\", ...) > 0 or type(a) ~= \"table\" then return math.min(a, ...) end\n"
     "  if #a == 0 then arbc_no_value() end\n"
     "  return math.min(table.unpack(a))\n"
     "end\n"},
    {"max",
     {"arbc_no_value"},
     "-- max(a, b, ...) of numbers, or max(xs) of a list (an empty list has no value).\n"
     "local function max(a, ...)\n"
     "  if select(\"#\", ...) > 0 or type(a) ~= \"table\" then return math.max(a, ...) end\n"
     "  if #a == 0 then arbc_no_value() end\n"
     "  return math.max(table.unpack(a))\n"
     "end\n"},
    {"now",
     {},
     "-- now(): the runtime clock in seconds (virtual in simulation).\n"
     "local function now() return PortMonitor.now() end\n"},
    {"vec3",
     {},
     "-- vec3(x, y, z): a vector, as the runtime passes them: a table with x, y and z.\n"
     "local function vec3(x, y, z) return { x = x, y = y, z = z } end\n"},
    {"arbc_vadd",
     {"vec3"},
     "local function arbc_vadd(a, b) return vec3(a.x + b.x, a.y + b.y, a.z + b.z) end\n"},
    {"arbc_vsub",
     {"vec3"},
     "local function arbc_vsub(a, b) return vec3(a.x - b.x, a.y - b.y, a.z - b.z) end\n"},
    {"arbc_vneg", {"vec3"}, "local function arbc_vneg(a) return vec3(-a.x, -a.y, -a.z) end\n"},
    {"arbc_vscale",
     {"vec3"},
     "-- A vector times a number, either way round.\n"
     "local function arbc_vscale(a, b)\n"
     "  if type(a) == \"number\" then a, b = b, a end\n"
     "  return vec3(a.x * b, a.y * b, a.z * b)\n"
     "end\n"},
    {"arbc_vdiv",
     {"vec3"},
     "local function arbc_vdiv(a, k) return vec3(a.x / k, a.y / k, a.z / k) end\n"},
    {"arbc_concat",
     {},
     "-- xs + ys of lists: a new list.\n"
     "local function arbc_concat(xs, ys)\n"
     "  local out = {}\n"
     "  for i = 1, #xs do out[#out + 1] = xs[i] end\n"
     "  for i = 1, #ys do out[#out + 1] = ys[i] end\n"
     "  return out\n"
     "end\n"},
    {"arbc_equal",
     {},
     "-- Structural equality of values (vec3, lists and records compare by content).\n"
     "local function arbc_equal(a, b)\n"
     "  if type(a) ~= \"table\" or type(b) ~= \"table\" then return a == b end\n"
     "  for k, v in pairs(a) do if not arbc_equal(v, b[k]) then return false end end\n"
     "  for k in pairs(b) do if a[k] == nil then return false end end\n"
     "  return true\n"
     "end\n"},
};

const Helper* find_helper(std::string_view name) {
  for (const Helper& h : kHelpers)
    if (h.name == name) return &h;
  return nullptr;
}

void add_with_needs(std::string_view name, std::set<std::string>& closure) {
  const Helper* h = find_helper(name);
  if (!h || !closure.insert(std::string(name)).second) return;
  for (std::string_view n : h->needs)
    if (!n.empty()) add_with_needs(n, closure);
}

// Lua globals the generated code or the helpers call; a spec name must not shadow them.
constexpr std::array<std::string_view, 21> kLuaGlobals = {
    "PortMonitor", "math",   "string",   "table",        "error",    "pcall",    "ipairs",
    "pairs",       "select", "type",     "setmetatable", "tostring", "rawequal", "next",
    "print",       "unpack", "tonumber", "assert",       "utf8",     "_ENV",     "_G"};

}  // namespace

bool is_builtin(std::string_view name) {
  for (const BuiltinInfo& b : kBuiltins)
    if (b.lua_helper == name) return true;
  return false;
}

bool is_reserved_lua_name(std::string_view name) {
  if (name.substr(0, 5) == "arbc_") return true;
  if (is_builtin(name)) return true;
  for (std::string_view g : kLuaGlobals)
    if (g == name) return true;
  return false;
}

std::set<std::string> helper_closure(const std::set<std::string>& used) {
  std::set<std::string> closure;
  for (const std::string& name : used) add_with_needs(name, closure);
  return closure;
}

std::string lua_prelude(const std::set<std::string>& used) {
  std::set<std::string> closure = helper_closure(used);
  std::string out;
  for (const Helper& h : kHelpers)
    if (closure.count(std::string(h.name))) out += h.source;
  return out;
}

}  // namespace arbc::codegen
