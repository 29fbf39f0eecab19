-- The Lua helpers of the spec language's builtins and of the generated code
-- (compiler/codegen/lua_prelude.h), embedded at build time: each generated monitor copies the
-- helpers it uses, in this file's order (a helper after the helpers it calls: Lua locals are
-- defined before use). A line `--@ helper NAME [needs OTHER]` opens a helper; its text, up to
-- the next such line, is copied as it is. This whole file is one Lua chunk, so `luac5.4 -p`
-- (ctest lua_compiles.kLuaPrelude) checks every helper, used or not.
--@ helper arbc_no_value
-- An expression without a value ends the callback: the runtime drops the message
-- with reason "no-value" (docs/runtime.md).
local function arbc_no_value() PortMonitor.novalue() end
--@ helper arbc_index needs arbc_no_value
-- xs[i], counting from 0 as the spec does; out of range has no value.
local function arbc_index(xs, i)
  local x = xs[i + 1]
  if x == nil then arbc_no_value() end
  return x
end
--@ helper arbc_fmod needs arbc_no_value
-- a % b of the spec: C's fmod, truncating (Lua's own % floors); math.fmod raises on an
-- int divided by int 0, which has no value instead (docs/language.md#numbers).
local function arbc_fmod(a, b)
  if b == 0 and math.type(a) == "integer" and math.type(b) == "integer" then
    arbc_no_value()
  end
  return math.fmod(a, b)
end
--@ helper len
-- len(xs): the number of elements of a list, or of bytes of a string.
local function len(xs) return #xs end
--@ helper arbc_best_by needs arbc_no_value
-- The first element of xs whose key(x) is best by `better`; none when xs is empty.
local function arbc_best_by(xs, key, better)
  local best, best_key = nil, nil
  for i = 1, #xs do
    local k = key(xs[i])
    if best == nil or better(k, best_key) then best, best_key = xs[i], k end
  end
  if best == nil then arbc_no_value() end
  return best
end
--@ helper min_by needs arbc_best_by
-- min_by(xs, f): the element with the smallest f(x).
local function min_by(xs, key) return arbc_best_by(xs, key, function(a, b) return a < b end) end
--@ helper max_by needs arbc_best_by
-- max_by(xs, f): the element with the largest f(x).
local function max_by(xs, key) return arbc_best_by(xs, key, function(a, b) return a > b end) end
--@ helper norm
-- norm(v): the length of a vec3.
local function norm(v) return math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z) end
--@ helper dist
-- dist(a, b): the Euclidean distance between two vec3.
local function dist(a, b)
  local dx, dy, dz = a.x - b.x, a.y - b.y, a.z - b.z
  return math.sqrt(dx * dx + dy * dy + dz * dz)
end
--@ helper abs
-- abs(x): the absolute value.
local function abs(x) return math.abs(x) end
--@ helper min needs arbc_no_value
-- min(a, b, ...) of numbers, or min(xs) of a list (an empty list has no value).
local function min(a, ...)
  if select("#", ...) > 0 or type(a) ~= "table" then return math.min(a, ...) end
  if #a == 0 then arbc_no_value() end
  return math.min(table.unpack(a))
end
--@ helper max needs arbc_no_value
-- max(a, b, ...) of numbers, or max(xs) of a list (an empty list has no value).
local function max(a, ...)
  if select("#", ...) > 0 or type(a) ~= "table" then return math.max(a, ...) end
  if #a == 0 then arbc_no_value() end
  return math.max(table.unpack(a))
end
--@ helper now
-- now(): the runtime clock in seconds (virtual in simulation).
local function now() return PortMonitor.now() end
--@ helper age
-- age(t): how long ago the stamp t ({sec, nanosec}) was, in seconds, on the run's clock read as
-- ROS 2 time (PortMonitor.stamp_now(): the simulated clock in simulation).
local function age(t) return PortMonitor.stamp_now() - (t.sec + t.nanosec * 1e-9) end

--@ helper vec3
-- vec3(x, y, z): a vector, as the runtime passes them: a table with x, y and z.
local function vec3(x, y, z) return { x = x, y = y, z = z } end
--@ helper arbc_vadd needs vec3
local function arbc_vadd(a, b) return vec3(a.x + b.x, a.y + b.y, a.z + b.z) end
--@ helper arbc_vsub needs vec3
local function arbc_vsub(a, b) return vec3(a.x - b.x, a.y - b.y, a.z - b.z) end
--@ helper arbc_vneg needs vec3
local function arbc_vneg(a) return vec3(-a.x, -a.y, -a.z) end
--@ helper arbc_vscale needs vec3
-- A vector times a number, either way round.
local function arbc_vscale(a, b)
  if type(a) == "number" then a, b = b, a end
  return vec3(a.x * b, a.y * b, a.z * b)
end
--@ helper arbc_vdiv needs vec3
local function arbc_vdiv(a, k) return vec3(a.x / k, a.y / k, a.z / k) end
--@ helper arbc_concat
-- xs + ys of lists: a new list.
local function arbc_concat(xs, ys)
  local out = {}
  for i = 1, #xs do out[#out + 1] = xs[i] end
  for i = 1, #ys do out[#out + 1] = ys[i] end
  return out
end
--@ helper arbc_equal
-- Structural equality of values (vec3, lists and records compare by content).
local function arbc_equal(a, b)
  if type(a) ~= "table" or type(b) ~= "table" then return a == b end
  for k, v in pairs(a) do if not arbc_equal(v, b[k]) then return false end end
  for k in pairs(b) do if a[k] == nil then return false end end
  return true
end
