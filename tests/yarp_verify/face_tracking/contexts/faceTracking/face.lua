-- face.lua: faces go to the gaze controller when the detector is sure enough; each one seen
-- keeps look-around quiet for a second.
require("yarp")

local MIN_CERTAINTY = 0.8
local FACE_LIFETIME = 1.0   -- seconds

PortMonitor.create = function(options)
  print("face monitor: " .. options:find("source"):asString() .. " -> " ..
        options:find("destination"):asString())
  return true
end

-- A face is (x y z certainty).
PortMonitor.accept = function(thing)
  local face = thing:asBottle()
  if face:size() < 4 or face:get(3):asFloat64() < MIN_CERTAINTY then
    return false
  end
  PortMonitor.setEvent("e_face_seen", FACE_LIFETIME)
  return true
end

-- The controller takes (x y z).
PortMonitor.update = function(thing)
  local face = thing:asBottle()
  face:pop()
  return thing
end
