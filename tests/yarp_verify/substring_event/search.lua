-- search.lua: search once the face is lost.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_face_lost")
  return true
end
