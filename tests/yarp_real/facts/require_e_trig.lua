-- require_e_trig.lua: delivers only while the event e_trig is present.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_trig")
  return true
end
