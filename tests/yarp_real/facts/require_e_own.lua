-- require_e_own.lua: delivers only while the event e_own is present.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_own")
  return true
end
