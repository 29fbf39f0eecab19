-- counter.lua: counts the messages of its connection in a global; each delivery carries it.
require("yarp")

count = 0

PortMonitor.update = function(thing)
  count = count + 1
  thing:asBottle():addInt32(count)
  return thing
end
