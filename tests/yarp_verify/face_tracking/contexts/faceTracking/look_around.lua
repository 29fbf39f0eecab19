-- look_around.lua: sweep the gaze while no face was seen recently.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_face_seen")
  return true
end
