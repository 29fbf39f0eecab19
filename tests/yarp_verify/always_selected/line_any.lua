-- line_any.lua: line.lua without its setConstraint: YARP selects it whatever the events.
require("yarp")

PortMonitor.create = function(options)
  return true
end

PortMonitor.accept = function(thing)
  return thing:asBottle():size() == 3
end
