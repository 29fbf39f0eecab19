-- C7, C11 (paper Listing 7): e_unreachable while the nearest object is beyond tool reach;
-- cleared when it is reachable again. Never delivers.
local TOOL_REACHABLE = 0.75

PortMonitor.accept = function(objects)
  local nearest
  for _, o in ipairs(objects) do
    if nearest == nil or o.dist < nearest.dist then nearest = o end
  end
  if nearest ~= nil and nearest.dist > TOOL_REACHABLE then
    PortMonitor.setEvent("e_unreachable")
  else
    PortMonitor.unsetEvent("e_unreachable")
  end
  return false
end
