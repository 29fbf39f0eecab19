-- require_e_pw.lua: delivers only while the event e_pw is present.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_pw")
  return true
end
