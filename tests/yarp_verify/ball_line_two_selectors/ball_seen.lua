-- ball_seen.lua: while the ball detector sees a ball, follow the ball.
require("yarp")

PortMonitor.accept = function(thing)
  if thing:asBottle():get(0):asInt32() == 1 then
    PortMonitor.setEvent("e_ball", 0.5)
    PortMonitor.unsetEvent("e_line")   -- no effect in YARP: line_seen.lua owns e_line
  end
  return false
end
