-- A hand-written monitor for `search` that tries to select every message, whatever the rule's
-- `when` says. The runtime refuses to load it: the constraint is app.json's.
PortMonitor.create = function(options)
  PortMonitor.setConstraint("true")
  return true
end
