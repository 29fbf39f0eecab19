-- C2 (paper Listing 4): put the held object into the bucket.
-- Constraint: e_taken and e_arm_idle
PortMonitor.update = function(bucket)
  return { verb = "put", pos = bucket }
end
