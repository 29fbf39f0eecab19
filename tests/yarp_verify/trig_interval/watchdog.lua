-- watchdog.lua: scans pass through; ten times a second trig() checks that they still come.
require("yarp")

local last_scan = 0

PortMonitor.create = function(options)
  PortMonitor.setTrigInterval(0.01)   -- a hundred times a second
  return true
end

PortMonitor.accept = function(thing)
  last_scan = yarp.now()
  PortMonitor.unsetEvent("e_laser_lost")
  return true
end

PortMonitor.trig = function()
  if yarp.now() - last_scan > 0.5 then
    PortMonitor.setEvent("e_laser_lost")
  end
end
