-- no_create_result.lua: create returns nothing.
require("yarp")

PortMonitor.create = function(options)
end
