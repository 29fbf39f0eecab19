-- Lets the first two counts through, then fails on purpose.
PortMonitor.accept = function(n)
  if n > 2 then error("too many: " .. n) end
  return true
end
PortMonitor.update = function(n) return {verb = "go", n = n} end
