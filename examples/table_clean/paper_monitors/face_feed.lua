-- C10's event part: e_face_detected for 1 s after each confident face. Never delivers.
PortMonitor.accept = function(face)
  if face.certainty >= 0.8 then PortMonitor.setEvent("e_face_detected", 1.0) end
  return false
end
