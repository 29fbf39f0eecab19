-- face.lua: the paper writes setEvent unqualified; here through a local alias.
require("yarp")
local setEvent = PortMonitor.setEvent

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_face")
  return true
end

PortMonitor.accept = function(thing)
  setEvent("e_face", 1.0)
  return true
end
