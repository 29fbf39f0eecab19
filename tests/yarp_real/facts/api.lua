-- api.lua: what PortMonitor and the yarp module offer; each delivery carries it.
require("yarp")

local report = {}

PortMonitor.create = function(options)
  PortMonitor.setConstraint("true")
  report[#report + 1] = "getConstraint_values=" .. select("#", PortMonitor.getConstraint())
  local names = {}
  for k, v in pairs(PortMonitor) do
    if type(v) == "function" and k ~= "create" and k ~= "update" and k ~= "accept" then
      names[#names + 1] = k
    end
  end
  table.sort(names)
  report[#report + 1] = "functions=" .. table.concat(names, ",")
  report[#report + 1] = "Time_now=" .. type(yarp.Time_now)
  report[#report + 1] = "now=" .. type(yarp.now())
  return true
end

PortMonitor.accept = function(thing)
  if thing:asBottle():get(0):asString() == "boom" then error("boom") end
  return true
end

PortMonitor.update = function(thing)
  for _, s in ipairs(report) do thing:asBottle():addString(s) end
  return thing
end
