-- require_e_q.lua: delivers only while the event e_q is present.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_q")
  return true
end
