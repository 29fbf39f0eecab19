-- Odd counts are rejected; even ones try string.find(40 a's, ("a?")^40 .. a^40 .. "b"), 2^40
-- ways to split the a's. The step budget stops each try (a counted monitor error); a rejection
-- in between keeps the connection out of quarantine, so the run goes on trying.
PortMonitor.accept = function(n)
  if n % 2 == 1 then return false end
  return string.find(string.rep("a", 40), string.rep("a?", 40) .. string.rep("a", 40) .. "b") ~= nil
end
