-- look_around.lua: look around while no camera sees the ball.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_ball")
  return true
end
