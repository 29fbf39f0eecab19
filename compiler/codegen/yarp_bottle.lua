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
    -- T[N] has exactly N elements, list<T, N> at most N: what the proof assumed.
    if t.size ~= nil and (b:size() > t.size or (t.fixed and b:size() ~= t.size)) then
      return nil
    end
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

-- An integer of t's width: any YARP integer (read whole, not through a double), or a float with
-- an integer value; nil outside t's range (docs/yarp.md#the-bottle-layout). A uint64 travels as
-- the int64 of its bits, every value of which is one of its.
local function arbc_read_int(v, t)
  local x
  if v:isInt8() or v:isInt16() or v:isInt32() or v:isInt64() then
    x = v:asInt64()
  else
    local f = arbc_read_number(v)
    x = f ~= nil and math.tointeger(f) or nil
  end
  if x == nil or t.bits == nil or t.bits == 64 then return x end
  local lo, hi = -(1 << (t.bits - 1)), (1 << (t.bits - 1)) - 1
  if t.unsigned then lo, hi = 0, (1 << t.bits) - 1 end
  if x < lo or x > hi then return nil end
  return x
end

-- A float32 is a double that rounds to itself in binary32 (NaN and the infinities included).
local function arbc_read_float(v, t)
  local x = arbc_read_number(v)
  if x == nil or t.bits ~= 32 or x ~= x or x == math.huge or x == -math.huge then return x end
  if math.abs(x) > 3.4028234663852886e38 then return nil end
  if string.unpack("<f", string.pack("<f", x)) ~= x then return nil end
  return x
end

arbc_read_item = function(v, t)
  if t.kind == "float" then return arbc_read_float(v, t) end
  if t.kind == "int" then return arbc_read_int(v, t) end
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
    if v:isString() and (t.size == nil or #v:asString() <= t.size) then return v:asString() end
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
    if t.bits == 32 then b:addFloat32(x + 0.0) else b:addFloat64(x + 0.0) end
  elseif t.kind == "int" then
    -- At the narrowest YARP integer that holds every value of t (YARP has no unsigned ones: a
    -- uint8 goes as an Int16); an int as before sized types, Int32 when the value fits.
    local bits = t.bits or 64
    if t.unsigned and bits < 64 then bits = bits * 2 end
    if bits == 8 then b:addInt8(x)
    elseif bits == 16 then b:addInt16(x)
    elseif bits == 32 or (t.bits == nil and x >= -2147483648 and x <= 2147483647) then b:addInt32(x)
    else b:addInt64(x) end
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
