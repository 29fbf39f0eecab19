-- Hand-written monitor used by script_alone.spec.
PortMonitor.accept = function(msg) return true end
