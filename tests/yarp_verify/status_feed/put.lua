-- put.lua: the paper's C2.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_taken and e_arm_idle")
  return true
end
