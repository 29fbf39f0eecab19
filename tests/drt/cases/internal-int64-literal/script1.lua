-- A hand-written monitor of the differential test (tests/drt).
PortMonitor.accept = function(msg)
  if msg then PortMonitor.setEvent("e3", 0.2) else PortMonitor.unsetEvent("e3") end
  return msg
end
