-- arm_state.lua: "l" and "r" mean the left and right arm are free; never delivered.
require("yarp")

PortMonitor.accept = function(thing)
  local b = thing:asBottle()
  if b:get(0):asString() == "left" then PortMonitor.setEvent("l", 1.0) end
  if b:get(1):asString() == "right" then PortMonitor.setEvent("r", 1.0) end
  return false
end
