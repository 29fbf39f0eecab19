-- ball.lua: the ball tracker's targets reach the controller while the user wants the ball.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_ball")
  return true
end

PortMonitor.accept = function(thing)
  -- a target is (x y z); drop empty detections
  return thing:asBottle():size() == 3
end
