-- status.lua: the paper's C3. Pick-and-place reports its state as an event name (e_taken,
-- e_arm_idle); the message itself is never delivered.
require("yarp")

PortMonitor.create = function(options)
  return true
end

PortMonitor.accept = function(thing)
  local status_event = thing:asBottle():get(0):asString()
  PortMonitor.setEvent(status_event, 0.5)
  return false
end
