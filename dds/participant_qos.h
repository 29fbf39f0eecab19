// The QoS arbc's DDS participant is made with: Fast-DDS's defaults as the user's XML profile
// sets them (FASTRTPS_DEFAULT_PROFILES_FILE, docs/distributed.md#confining-dds-to-one-machine),
// then arbc's own settings over them: a name, a short lease, and over shared memory a
// participant id clear of segments that killed processes left (dds/shm_participant_id.h).
#pragma once

#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <string>

namespace arbc::dds {

struct ParticipantSettings {
  std::string name;  // shown by DDS tools
  int domain = 0;
  // Wall seconds without a word from a peer participant before it counts as gone; Fast-DDS's
  // default is 20, too long to report a crashed process in time (at least 0.5).
  double lease_seconds = 3;
};

// False with *error when the profile that FASTRTPS_DEFAULT_PROFILES_FILE names cannot be read
// (Fast-DDS alone would log it and run on its defaults: every transport, every interface).
// *note: a line for the run's log (the id chosen is past the initial peers' reach), or empty.
bool participant_qos(const ParticipantSettings& settings,
                     eprosima::fastdds::dds::DomainParticipantQos* qos, std::string* note,
                     std::string* error);

}  // namespace arbc::dds
