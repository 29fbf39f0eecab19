-- joystick.lua: the joystick takes over when its button is pressed, by rewriting its own
-- constraint.
require("yarp")

PortMonitor.create = function(options)
  PortMonitor.setConstraint("false")
  return true
end

PortMonitor.accept = function(thing)
  if thing:asBottle():get(3):asInt32() == 1 then
    PortMonitor.setConstraint("true")
  end
  return true
end
