-- plain.lua: a monitor that does nothing (a constraint can come from the carrier string).
require("yarp")
