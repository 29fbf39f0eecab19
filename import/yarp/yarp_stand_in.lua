-- A stand-in for YARP's Lua bindings (`require("yarp")`), run in a monitor script's sandbox
-- when arbc reads a YARP application (import/yarp/yarp_stand_in.h says what it offers; it is
-- compiled into arbc from this file). Values follow YARP's: out-of-range get() gives a null
-- Value, whose asString() is "" and asInt32() is 0; asList() of a non-list is nil.

local function missing(kind)
  return function(_, key)
    error("arbc's stand-in for YARP's Lua bindings has no " .. kind .. "." .. tostring(key) ..
          " (docs/yarp.md lists what it offers)", 2)
  end
end

local Value, Bottle, Property, Vector = {}, {}, {}, {}
Value.__index = setmetatable({}, {__index = missing("Value")})
Bottle.__index = setmetatable({}, {__index = missing("Bottle")})
Property.__index = setmetatable({}, {__index = missing("Property")})
Vector.__index = setmetatable({}, {__index = missing("Vector")})
local V, B, P, VEC = Value.__index, Bottle.__index, Property.__index, Vector.__index

local function new_value(kind, v) return setmetatable({kind = kind, v = v}, Value) end
local function new_bottle() return setmetatable({items = {}}, Bottle) end
local function to_value(x)
  if getmetatable(x) == Value then return x end
  if getmetatable(x) == Bottle then return new_value("list", x) end
  if math.type(x) == "integer" then return new_value("int", x) end
  if type(x) == "number" then return new_value("float", x) end
  if type(x) == "boolean" then return new_value("bool", x) end
  if x == nil then return new_value("null") end
  return new_value("string", tostring(x))
end

function V:asString() return self.kind == "string" and self.v or "" end
function V:asInt32()
  if self.kind == "int" or self.kind == "float" then return math.floor(self.v) end
  if self.kind == "bool" then return self.v and 1 or 0 end
  return 0
end
V.asInt64, V.asInt16, V.asInt8, V.asInt, V.asVocab32 = V.asInt32, V.asInt32, V.asInt32,
  V.asInt32, V.asInt32
function V:asFloat64()
  if self.kind == "int" or self.kind == "float" then return self.v + 0.0 end
  return 0.0
end
V.asFloat32, V.asDouble = V.asFloat64, V.asFloat64
function V:asBool()
  if self.kind == "bool" then return self.v end
  if self.kind == "int" or self.kind == "float" then return self.v ~= 0 end
  return false
end
function V:asList() return self.kind == "list" and self.v or nil end
function V:isString() return self.kind == "string" end
function V:isInt32() return self.kind == "int" end
V.isInt64, V.isInt16, V.isInt8, V.isInt = V.isInt32, V.isInt32, V.isInt32, V.isInt32
function V:isFloat64() return self.kind == "float" end
V.isFloat32, V.isDouble = V.isFloat64, V.isFloat64
function V:isBool() return self.kind == "bool" end
function V:isList() return self.kind == "list" end
function V:isNull() return self.kind == "null" end
function V:isVocab32() return false end
function V:toString()
  if self.kind == "list" then return "(" .. self.v:toString() .. ")" end
  if self.kind == "null" then return "" end
  if self.kind == "string" then return self.v end
  return tostring(self.v)
end
function V:find(key) return self.kind == "list" and self.v:find(key) or new_value("null") end
function V:check(key) return self.kind == "list" and self.v:check(key) or false end

local function parse_into(b, text, pos)
  while pos <= #text do
    local c = text:sub(pos, pos)
    if c:match("%s") then
      pos = pos + 1
    elseif c == "(" then
      local inner = b:addList()
      pos = parse_into(inner, text, pos + 1)
    elseif c == ")" then
      return pos + 1
    elseif c == '"' then
      local close = text:find('"', pos + 1, true) or (#text + 1)
      b:addString(text:sub(pos + 1, close - 1))
      pos = close + 1
    else
      local word = text:match("^[^%s()]+", pos)
      local n = math.tointeger(tonumber(word)) or tonumber(word)
      if n ~= nil then b.items[#b.items + 1] = to_value(n) else b:addString(word) end
      pos = pos + #word
    end
  end
  return pos
end

function B:size() return #self.items end
function B:get(i)
  if type(i) ~= "number" then error("Bottle:get expects an index", 2) end
  return self.items[i + 1] or new_value("null")
end
function B:addString(s) self.items[#self.items + 1] = new_value("string", tostring(s)) end
function B:addInt32(i) self.items[#self.items + 1] = new_value("int", math.floor(i)) end
B.addInt64, B.addInt16, B.addInt8, B.addInt, B.addVocab32 = B.addInt32, B.addInt32,
  B.addInt32, B.addInt32, B.addInt32
function B:addFloat64(x) self.items[#self.items + 1] = new_value("float", x + 0.0) end
B.addFloat32, B.addDouble = B.addFloat64, B.addFloat64
function B:addBool(x) self.items[#self.items + 1] = new_value("bool", x and true or false) end
function B:addList()
  local inner = new_bottle()
  self.items[#self.items + 1] = new_value("list", inner)
  return inner
end
function B:add(x) self.items[#self.items + 1] = to_value(x) end
function B:clear() self.items = {} end
function B:copy(other) self.items = {}; for i, v in ipairs(other.items) do self.items[i] = v end end
function B:fromString(text) self.items = {}; parse_into(self, text, 1) end
function B:toString()
  local parts = {}
  for i, v in ipairs(self.items) do
    parts[i] = v.kind == "string" and v.v:find("[%s()]") and ('"' .. v.v .. '"') or v:toString()
  end
  return table.concat(parts, " ")
end
function B:isNull() return false end
function B:pop()
  local v = self.items[#self.items]
  self.items[#self.items] = nil
  return v or new_value("null")
end
function B:tail()
  local t = new_bottle()
  for i = 2, #self.items do t.items[i - 1] = self.items[i] end
  return t
end
function B:find(key)
  for _, v in ipairs(self.items) do
    if v.kind == "list" and v.v.items[1] and v.v.items[1]:toString() == key then
      return v.v.items[2] or new_value("null")
    end
  end
  for i, v in ipairs(self.items) do
    if v:toString() == key then return self.items[i + 1] or new_value("null") end
  end
  return new_value("null")
end
function B:check(key) return not self:find(key):isNull() end
function B:findGroup(key)
  for _, v in ipairs(self.items) do
    if v.kind == "list" and v.v.items[1] and v.v.items[1]:toString() == key then return v.v end
  end
  return new_bottle()
end

function P:put(key, x) self.map[key] = to_value(x) end
function P:find(key) return self.map[key] or new_value("null") end
function P:check(key, default)
  if default ~= nil then return self.map[key] or to_value(default) end
  return self.map[key] ~= nil
end
function P:clear() self.map = {} end
function P:fromString(text)
  local b = new_bottle()
  b:fromString(text)
  for _, v in ipairs(b.items) do
    if v.kind == "list" and v.v.items[1] then self.map[v.v.items[1]:toString()] = v.v.items[2] end
  end
end
function P:toString()
  local parts = {}
  for k, v in pairs(self.map) do parts[#parts + 1] = "(" .. k .. " " .. v:toString() .. ")" end
  table.sort(parts)
  return table.concat(parts, " ")
end

function VEC:size() return #self.data end
function VEC:get(i) return self.data[i + 1] or 0.0 end
function VEC:set(i, x) self.data[i + 1] = x end
function VEC:push_back(x) self.data[#self.data + 1] = x end
function VEC:resize(n) for i = 1, n do self.data[i] = self.data[i] or 0.0 end end
function VEC:zero() for i = 1, #self.data do self.data[i] = 0.0 end end
function VEC:toString() return table.concat(self.data, " ") end

local clock = 1000.0
local yarp_module = {
  Bottle = function(text)
    local b = new_bottle()
    if text ~= nil then b:fromString(text) end
    return b
  end,
  Value = function(x) return to_value(x) end,
  Property = function(text)
    local p = setmetatable({map = {}}, Property)
    if text ~= nil then p:fromString(text) end
    return p
  end,
  Vector = function(n, x)
    local v = setmetatable({data = {}}, Vector)
    for i = 1, (n or 0) do v.data[i] = x or 0.0 end
    return v
  end,
  now = function() return clock end,
  Time_now = function() return clock end,
  Time_delay = function() end,
  delay = function() end,
  Network = function() return setmetatable({}, {__index = function() return function() return true end end}) end,
  Network_init = function() end,
  Network_fini = function() end,
}
yarp = setmetatable(yarp_module, {__index = missing("yarp")})

function require(name)
  if name == "yarp" then
    __arbc_yarp_required = true  -- YARP needs it before any callback that gets a YARP object
    return yarp
  end
  error("module '" .. tostring(name) .. "' not found (arbc's analysis offers only \"yarp\")", 2)
end

local Things = {__index = setmetatable({}, {__index = missing("Things")})}
function Things.__index:asBottle() return self.bottle end
function __arbc_thing(text)
  clock = clock + 0.1
  return setmetatable({bottle = yarp.Bottle(text)}, Things)
end
function __arbc_options(t)
  local p = yarp.Property()
  for k, v in pairs(t) do p:put(k, v) end
  return p
end
