-- right.lua: reach with the right arm when only the right one is free.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("r and not l")
  return true
end
