-- Bottles and spec values (docs/yarp.md#the-bottle-layout). Reading gives nil for a
-- Bottle without the layout; nothing here raises on a value of the declared type.
local arbc_read_item

local function arbc_read_number(v)
  if v:isFloat64() or v:isInt32() or v:isInt64() or v:isInt16() or v:isInt8()
     or v:isFloat32() then
    return v:asFloat64()
  end
  return nil
end

local function arbc_read_contents(b, t)
  if t.kind == "vec3" then
    if b:size() ~= 3 then return nil end
    local x, y, z = arbc_read_number(b:get(0)), arbc_read_number(b:get(1)), arbc_read_number(b:get(2))
    if x == nil or y == nil or z == nil then return nil end
    return { x = x, y = y, z = z }
  elseif t.kind == "list" then
    local out = {}
    for i = 0, b:size() - 1 do
      local x = arbc_read_item(b:get(i), t.element)
      if x == nil then return nil end
      out[#out + 1] = x
    end
    return out
  elseif t.kind == "record" then
    local out = {}
    for i = 0, b:size() - 1 do
      local pair = b:get(i)
      if pair:isList() and pair:asList():size() == 2 then
        local name = pair:asList():get(0):asString()
        local ft = t.fields[name]
        if ft ~= nil and out[name] == nil then
          local x = arbc_read_item(pair:asList():get(1), ft)
          if x == nil then return nil end
          out[name] = x
        end
      end
    end
    for _, name in ipairs(t.order) do
      if out[name] == nil then return nil end
    end
    return out
  elseif b:size() == 1 then
    return arbc_read_item(b:get(0), t)
  end
  return nil
end

arbc_read_item = function(v, t)
  if t.kind == "float" then return arbc_read_number(v) end
  if t.kind == "int" then
    local x = arbc_read_number(v)
    if x == nil then return nil end
    return math.tointeger(x)
  end
  if t.kind == "bool" then
    if v:isString() then
      local s = v:asString()
      if s == "true" then return true elseif s == "false" then return false end
      return nil
    end
    local x = arbc_read_number(v)
    if x == nil then return nil end
    return x ~= 0
  end
  if t.kind == "string" then
    if v:isString() then return v:asString() end
    return nil
  end
  if v:isList() then return arbc_read_contents(v:asList(), t) end
  return nil
end

-- The value a message carries, or nil.
local function arbc_read(thing, t)
  local b = thing:asBottle()
  if b == nil then return nil end
  return arbc_read_contents(b, t)
end

local arbc_write_contents

local function arbc_write_item(b, x, t)
  if t.kind == "float" then
    b:addFloat64(x + 0.0)
  elseif t.kind == "int" then
    if x >= -2147483648 and x <= 2147483647 then b:addInt32(x) else b:addInt64(x) end
  elseif t.kind == "bool" then
    b:addInt32(x and 1 or 0)
  elseif t.kind == "string" then
    b:addString(x)
  else
    arbc_write_contents(b:addList(), x, t)
  end
end

arbc_write_contents = function(b, x, t)
  if t.kind == "vec3" then
    b:addFloat64((x.x or x[1]) + 0.0)
    b:addFloat64((x.y or x[2]) + 0.0)
    b:addFloat64((x.z or x[3]) + 0.0)
  elseif t.kind == "list" then
    for i = 1, #x do arbc_write_item(b, x[i], t.element) end
  elseif t.kind == "record" then
    for _, name in ipairs(t.order) do
      local pair = b:addList()
      pair:addString(name)
      arbc_write_item(pair, x[name], t.fields[name])
    end
  else
    arbc_write_item(b, x, t)
  end
end

-- A new Bottle holding value x of type t.
local function arbc_write(x, t)
  local b = yarp.Bottle()
  arbc_write_contents(b, x, t)
  return b
end
