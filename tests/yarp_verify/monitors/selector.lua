-- selector.lua: the user's command ("ball", "line" or "stop") selects what the controller
-- follows. Commands are not targets: this connection never delivers, it only sets events.
require("yarp")

PortMonitor.create = function(options)
  return true
end

PortMonitor.accept = function(thing)
  local cmd = thing:asBottle():get(0):asString()
  if cmd == "ball" then
    PortMonitor.unsetEvent("e_line")
    PortMonitor.setEvent("e_ball")
  elseif cmd == "line" then
    PortMonitor.unsetEvent("e_ball")
    PortMonitor.setEvent("e_line")
  elseif cmd == "stop" then
    PortMonitor.unsetEvent("e_ball")
    PortMonitor.unsetEvent("e_line")
  end
  return false
end

PortMonitor.destroy = function()
  PortMonitor.unsetEvent("e_ball")
  PortMonitor.unsetEvent("e_line")
end
