-- C3, C6, C12 (paper Listing 5): PickAndPlace's status flags become events for 0.5 s; a flag
-- the status lacks is unset. Never delivers.
local FLAGS = { "e_taken", "e_arm_idle" }

PortMonitor.accept = function(status)
  local has = {}
  for _, f in ipairs(status) do has[f] = true end
  for _, f in ipairs(FLAGS) do
    if has[f] then PortMonitor.setEvent(f, 0.5) else PortMonitor.unsetEvent(f) end
  end
  return false
end
