-- line.lua: the line tracker's targets reach the controller while the user wants the line.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_line")
  return true
end

PortMonitor.accept = function(thing)
  return thing:asBottle():size() == 3
end
