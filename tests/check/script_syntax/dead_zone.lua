-- Drops twists inside the joystick's dead zone.
PortMonitor.accept = function(twist)
  if math.abs(twist) < 0.05 then
    return false
  retrun true
end
