-- require_e1_or_e10.lua: delivers while e1 or e10 is present (YARP: `e1` is part of `e10`).
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e1 or e10")
  return true
end

PortMonitor.trig = function()
end
