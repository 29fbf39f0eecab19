// arbc's DDS participant QoS (dds/participant_qos.h).
#include "dds/participant_qos.h"

#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.h>

#include <algorithm>
#include <cstdlib>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <filesystem>

#include "dds/shm_participant_id.h"

namespace arbc::dds {

namespace {

namespace fdds = eprosima::fastdds::dds;
using ReturnCode_t = eprosima::fastrtps::types::ReturnCode_t;

// Loads the profile FASTRTPS_DEFAULT_PROFILES_FILE names, if any. Fast-DDS itself only logs a
// file it cannot read and goes on with its defaults, so a run meant for UDP on one interface
// would run on every transport and interface without a word: refuse it instead.
bool load_named_profile(fdds::DomainParticipantFactory* factory, std::string* error) {
  const char* path = std::getenv("FASTRTPS_DEFAULT_PROFILES_FILE");
  if (!path || !*path) return true;
  std::error_code ec;
  bool exists = std::filesystem::is_regular_file(path, ec);
  if (exists && factory->load_XML_profiles_file(path) == ReturnCode_t::RETCODE_OK) return true;
  *error = std::string("DDS: FASTRTPS_DEFAULT_PROFILES_FILE names ") + path +
           (exists ? ", which is not a Fast-DDS profile Fast-DDS can read (it said why above)"
                   : ", which is not a file") +
           "; fix it, or unset FASTRTPS_DEFAULT_PROFILES_FILE to run on Fast-DDS's defaults";
  return false;
}

// Whether the participant will talk over shared memory: Fast-DDS's built-in transports include
// it, and a profile may name it among its own.
bool uses_shared_memory(const fdds::DomainParticipantQos& qos) {
  if (qos.transport().use_builtin_transports) return true;
  for (const auto& descriptor : qos.transport().user_transports) {
    if (std::dynamic_pointer_cast<eprosima::fastdds::rtps::SharedMemTransportDescriptor>(
            descriptor)) {
      return true;
    }
  }
  return false;
}

// Over shared memory, a participant id whose ports no earlier process left a segment for
// (dds/shm_participant_id.h); an id the profile sets stays. Returns the id (-1: Fast-DDS's).
int choose_participant_id(fdds::DomainParticipantQos& qos, int domain) {
  auto& wire = qos.wire_protocol();
  if (wire.participant_id >= 0 || !uses_shared_memory(qos)) return wire.participant_id;
  DdsPortPlan plan;
  plan.base = wire.port.portBase;
  plan.domain_gain = wire.port.domainIDGain;
  plan.participant_gain = wire.port.participantIDGain;
  plan.discovery_unicast_offset = wire.port.offsetd1;
  plan.user_unicast_offset = wire.port.offsetd3;
  wire.participant_id = participant_id_clear_of_segments(plan, domain);
  return wire.participant_id;
}

// An initial peer given without a port stands for the first few participant ids on that host
// (Fast-DDS's maxInitialPeersRange, 4 unless a transport says otherwise): a participant whose id
// is past them is found only by peers it announces itself to.
bool id_beyond_initial_peers(const fdds::DomainParticipantQos& qos, int id) {
  uint32_t reach = 4;
  for (const auto& descriptor : qos.transport().user_transports) {
    reach = std::min(reach, descriptor->maxInitialPeersRange);
  }
  for (const auto& peer : qos.wire_protocol().builtin.initialPeersList) {
    if (peer.port == 0 && id >= static_cast<int>(reach)) return true;
  }
  return false;
}

}  // namespace

bool participant_qos(const ParticipantSettings& settings, fdds::DomainParticipantQos* qos,
                     std::string* note, std::string* error) {
  fdds::DomainParticipantFactory* factory = fdds::DomainParticipantFactory::get_instance();
  // Fast-DDS reads the XML profiles only when asked, or in create_participant; before that
  // the default QoS is its built-in one. Without this the profile's participant (transports,
  // interfaces, discovery peers) was silently ignored: see dds_profile_applies.
  if (!load_named_profile(factory, error)) return false;
  factory->load_profiles();
  *qos = factory->get_default_participant_qos();
  qos->name(settings.name);
  auto& discovery = qos->wire_protocol().builtin.discovery_config;
  double lease = std::max(0.5, settings.lease_seconds);
  discovery.leaseDuration = eprosima::fastrtps::Duration_t(lease);
  discovery.leaseDuration_announcementperiod = eprosima::fastrtps::Duration_t(lease / 3);
  int id = choose_participant_id(*qos, settings.domain);
  note->clear();
  if (id_beyond_initial_peers(*qos, id)) {
    *note = "DDS: participant id " + std::to_string(id) +
            ": the lower ids' shared-memory ports are taken, by live processes or by segments "
            "that killed ones left in /dev/shm (fastrtps_port*); two processes that both sit "
            "past the initial peers' reach never find each other: give the initial peers their "
            "ports, or remove the segments no running process uses";
  }
  return true;
}

}  // namespace arbc::dds
