-- face_status.lua: the detector's status ("seen" or "lost") as events; never delivered.
require("yarp")

PortMonitor.accept = function(thing)
  local status = thing:asBottle():get(0):asString()
  if status == "seen" then
    PortMonitor.setEvent("e_face", 2.0)
  elseif status == "lost" then
    PortMonitor.setEvent("e_face_lost", 2.0)
  end
  return false
end
