-- ball_typo.lua: ball.lua with its constraint misspelt (e_bal): no monitor sets e_bal.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_bal")
  return true
end

PortMonitor.accept = function(thing)
  -- a target is (x y z); drop empty detections
  return thing:asBottle():size() == 3
end
