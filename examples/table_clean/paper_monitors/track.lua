-- C8: track a confident face. Higher priority than search: while this rule could deliver it
-- holds act_track for 1 s, which search's constraint excludes.
-- Constraint: e_unreachable and e_arm_idle and e_pull_idle and act_track
PortMonitor.accept = function(face)
  if not (PortMonitor.hasEvent("e_unreachable") and PortMonitor.hasEvent("e_arm_idle")
          and PortMonitor.hasEvent("e_pull_idle")) then
    return false
  end
  PortMonitor.setEvent("act_track", 1.0)
  return face.certainty >= 0.8
end

PortMonitor.update = function(face)
  return face.pos
end
