-- set_on_message.lua: a message "set NAME [LIFETIME]" or "unset NAME" sets or unsets the event;
-- never delivers.
require("yarp")

PortMonitor.accept = function(thing)
  local b = thing:asBottle()
  local what, name = b:get(0):asString(), b:get(1):asString()
  if what == "set" and b:size() > 2 then
    PortMonitor.setEvent(name, b:get(2):asFloat64())
  elseif what == "set" then
    PortMonitor.setEvent(name)
  elseif what == "unset" then
    PortMonitor.unsetEvent(name)
  end
  return false
end
