-- callbacks.lua: reports, in each delivered message, what create received and which callbacks
-- ran, so a test can read them.
require("yarp")

local created = "no"
local accepts = 0
local info = {}

PortMonitor.create = function(options)
  created = "yes"
  for _, key in ipairs({"source", "destination", "carrier", "type", "sender_side",
                        "receiver_side"}) do
    info[#info + 1] = key .. "=" .. options:find(key):toString()
  end
  info[#info + 1] = "filename_ends=" .. tostring(options:find("filename"):asString():match("callbacks.lua$") ~= nil)
  return true
end

PortMonitor.accept = function(thing)
  accepts = accepts + 1
  return thing:asBottle() ~= nil
end

PortMonitor.update = function(thing)
  local b = thing:asBottle()
  b:addString("create=" .. created)
  b:addString("accepts=" .. accepts)
  for _, s in ipairs(info) do b:addString(s) end
  return thing
end
