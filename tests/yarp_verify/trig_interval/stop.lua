-- stop.lua: the safety module's zero velocity reaches the base once the laser is lost.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_laser_lost")
  return true
end
