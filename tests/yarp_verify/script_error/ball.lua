-- ball.lua: create sets the constraint but returns nothing, so YARP refuses the connection.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_ball")
end
