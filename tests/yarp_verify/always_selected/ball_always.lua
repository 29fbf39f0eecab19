-- ball_always.lua: ball.lua with a constraint that holds whatever the events.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_ball or not e_ball")
  return true
end

PortMonitor.accept = function(thing)
  -- a target is (x y z); drop empty detections
  return thing:asBottle():size() == 3
end
