-- C1 (paper Listing 3): take the nearest object when it is within hand reach.
-- Constraint: not e_taken and e_arm_idle and e_pull_idle
local HAND_REACHABLE = 0.40
local target

PortMonitor.accept = function(objects)
  target = nil
  for _, o in ipairs(objects) do
    if target == nil or o.dist < target.dist then target = o end
  end
  return target ~= nil and target.dist <= HAND_REACHABLE
end

PortMonitor.update = function(objects)
  return { verb = "take", pos = target.pos }
end
