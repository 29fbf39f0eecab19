-- bad_constraint_trig.lua: a constraint that is not Lua, and a trig that sets e_trig.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_never &&")
  return true
end

PortMonitor.trig = function()
  PortMonitor.setEvent("e_trig", 0.3)
end
