-- trig_counter.lua: counts trig() calls; each delivery carries the count and the interval
-- asked for.
require("yarp")

local trigs = 0

PortMonitor.create = function(options)
  if options:find("source"):asString():match("timed") then
    PortMonitor.setTrigInterval(0.005)   -- every 5 ms, if the unit were seconds
  end
  return true
end

PortMonitor.trig = function()
  trigs = trigs + 1
end

PortMonitor.update = function(thing)
  thing:asBottle():addInt32(trigs)
  return thing
end
