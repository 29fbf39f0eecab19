-- right_cam.lua: the right camera's detections keep e_ball alive; never delivered.
require("yarp")

PortMonitor.accept = function(thing)
  if thing:asBottle():get(0):asInt32() == 1 then
    PortMonitor.setEvent("e_ball", 1.0)
  end
  return false
end
