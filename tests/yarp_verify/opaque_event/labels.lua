-- labels.lua: each label the detector reports ("ball", "line") becomes the event e_<label>.
require("yarp")

PortMonitor.accept = function(thing)
  local label = thing:asBottle():get(0):asString()
  if label ~= "" then
    PortMonitor.setEvent("e_" .. label, 0.5)
  end
  return false
end
