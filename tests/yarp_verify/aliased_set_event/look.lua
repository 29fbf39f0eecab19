-- look.lua: look around while no face was seen for a second.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_face")
  return true
end
