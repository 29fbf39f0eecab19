-- line.lua
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_ball")
  return true
end
