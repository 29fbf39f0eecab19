-- C1 (paper Listing 2): every face refreshes e_face_detected for one second, and the face's
-- position goes to the head. Constraint: true
PortMonitor.accept = function(face)
  PortMonitor.setEvent("e_face_detected", 1.0)
  return true
end

PortMonitor.update = function(face)
  return face.pos
end
