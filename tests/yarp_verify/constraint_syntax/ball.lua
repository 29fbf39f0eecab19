-- ball.lua: the ball, unless the line is selected (written the C++ way).
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_ball && !e_line")
  return true
end
