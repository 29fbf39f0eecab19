-- Rule `go`: every third count becomes a command while the arm is idle.
PortMonitor.accept = function(n)
  return n % 3 == 0
end

PortMonitor.update = function(n)
  return { verb = "go", n = n }
end
