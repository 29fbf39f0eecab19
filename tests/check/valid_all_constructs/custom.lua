-- A hand-written monitor for the `custom` rule of valid_all_constructs.spec.
PortMonitor.accept = function(msg) return msg.certainty > 0.5 end
PortMonitor.update = function(msg) return "custom" end
