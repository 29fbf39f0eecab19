-- left.lua: reach with the left arm when it is free and the right one is not.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("l and not r")
  return true
end
