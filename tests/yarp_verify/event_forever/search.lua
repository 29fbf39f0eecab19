-- search.lua: search while there is no face.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_face")
  return true
end

PortMonitor.accept = function(thing)
  PortMonitor.unsetEvent("e_face")   -- searching again: forget the last face
  return true
end
