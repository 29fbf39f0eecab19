-- C4 (paper Listing 6): pull the nearest object when it is within tool reach; cancel the
-- pulling once it is within hand reach. Constraint: not e_taken and e_arm_idle
local HAND_REACHABLE = 0.40
local TOOL_REACHABLE = 0.75
local target

PortMonitor.accept = function(objects)
  target = nil
  for _, o in ipairs(objects) do
    if target == nil or o.dist < target.dist then target = o end
  end
  return target ~= nil and target.dist <= TOOL_REACHABLE
end

PortMonitor.update = function(objects)
  if target.dist <= HAND_REACHABLE then return { verb = "cancel", pos = target.pos } end
  return { verb = "pull", pos = target.pos }
end
