-- line_seen.lua: while the line detector sees a line, follow the line.
require("yarp")

PortMonitor.accept = function(thing)
  if thing:asBottle():get(0):asInt32() == 1 then
    PortMonitor.setEvent("e_line", 0.5)
    PortMonitor.unsetEvent("e_ball")   -- no effect in YARP: ball_seen.lua owns e_ball
  end
  return false
end
