-- A hand-written monitor that sets an event under a name it computes: arbc's reading of the
-- script (the names passed to setEvent as literals) cannot know it sets e_ready.
PortMonitor.accept = function(thing)
  local name = "e_" .. "ready"
  PortMonitor.setEvent(name)
  return true
end
