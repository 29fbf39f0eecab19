-- Feed: Arm.status -> Arm.cmd's container. Sets e_idle (0.5 s) while the arm says "idle".
PortMonitor.accept = function(status)
  local idle = false
  for _, flag in ipairs(status) do
    if flag == "idle" then idle = true end
  end
  if idle then PortMonitor.setEvent("e_idle", 0.5) else PortMonitor.unsetEvent("e_idle") end
  return true
end
