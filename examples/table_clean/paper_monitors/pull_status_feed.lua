-- C5, C13: PullObject's status flag e_pull_idle becomes an event for 0.5 s. Never delivers.
PortMonitor.accept = function(status)
  local idle = false
  for _, f in ipairs(status) do
    if f == "e_pull_idle" then idle = true end
  end
  if idle then PortMonitor.setEvent("e_pull_idle", 0.5) else PortMonitor.unsetEvent("e_pull_idle") end
  return false
end
