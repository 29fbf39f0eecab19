-- drive.lua: the planner drives the base while the laser works.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_laser_lost")
  return true
end
