-- A hand-written monitor of the differential test (tests/drt).
PortMonitor.accept = function(msg)
  if msg then PortMonitor.setEvent("e2", 0.2) else PortMonitor.unsetEvent("e2") end
  return msg
end
