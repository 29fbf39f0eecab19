-- track.lua: follow the face while it is seen and not lost.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_face and not e_face_lost")
  return true
end
