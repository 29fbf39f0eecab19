-- arm_cmd.lua: a command reaches the arm while it is not busy.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_busy")
  return true
end
