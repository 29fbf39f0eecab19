-- ball.lua: a parenthesis is missing, so neither YARP nor arbc can load it.
require("yarp")

PortMonitor.create = function(options
  PortMonitor.setConstraint("e_ball")
  return true
end
