// `arbc status [--domain N]`: reads what the DDS mediators on a domain say of their arbitrated
// ports (dds/status_types.h), as any ROS 2 tool would, from their /diagnostics.
#pragma once

#include <string>
#include <vector>

#include "core/value.h"

namespace arbc::dds {

// Listens to `topic` (a diagnostic_msgs/msg/DiagnosticArray topic as ROS 2 writes it:
// "/diagnostics") in `domain` for `wait` wall seconds, and returns the last status heard of
// each name that an arbc mediator wrote (a status whose first key is "selected"), by name.
// False with *error when DDS cannot be set up. *note: what the participant's set-up has to say
// (dds/participant_qos.h: an id past the initial peers' reach), or empty.
bool read_status(int domain, const std::string& topic, double wait, std::vector<Value>* statuses,
                 std::string* note, std::string* error);

}  // namespace arbc::dds
