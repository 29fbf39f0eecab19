-- A hand-written monitor of the differential test (tests/drt).
PortMonitor.accept = function(msg)
  if true then PortMonitor.setEvent("e1", 0.2) else PortMonitor.unsetEvent("e1") end
  return true
end
