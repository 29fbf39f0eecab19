-- take.lua: the paper's C1.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_taken and e_arm_idle")
  return true
end
