-- C8: track a confident face. Higher priority than search: each face it delivers holds
-- act_track for 1 s (the runtime sets it on delivery, app.json's activity_event), which
-- search's constraint excludes.
-- Constraint: e_unreachable and e_arm_idle and e_pull_idle
PortMonitor.accept = function(face)
  return face.certainty >= 0.8
end

PortMonitor.update = function(face)
  return face.pos
end
