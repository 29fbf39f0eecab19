-- face.lua: a face takes the gaze, and tells the search to wait.
require("yarp")

PortMonitor.accept = function(thing)
  PortMonitor.setEvent("e_face")
  return true
end
