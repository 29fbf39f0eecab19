-- arm_state.lua: the arm's state ("busy" or "idle") as the event e_busy; never delivered.
require("yarp")

PortMonitor.accept = function(thing)
  if thing:asBottle():get(0):asString() == "busy" then
    PortMonitor.setEvent("e_busy", 1.0)
  else
    PortMonitor.unsetEvent("e_busy")
  end
  return false
end
