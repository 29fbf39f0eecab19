-- C10 (paper Listing 8): ask the person for help (throttled to one request per 5 s by the
-- connection). Constraint: e_unreachable and e_face_detected
PortMonitor.update = function(face)
  return "Please put the object closer!"
end
