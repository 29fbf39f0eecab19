// Which DDS participant id to ask Fast-DDS for when shared memory is among the transports.
//
// Fast-DDS 2.9 names a shared-memory port's segment after the port's number
// (/dev/shm/fastrtps_port<N>), and the number follows from the domain and the participant id.
// A process that is killed leaves its segments behind. Left to itself, Fast-DDS gives the
// process started in its place the same participant id, hence the same port numbers: it finds
// the dead process's segment, removes it and makes a new one under the same name. A survivor
// that was writing to the old segment still has it mapped and keeps writing into it, so the
// restarted process is matched but sometimes never hears a sample (Fast-DDS issues 5053 and
// 5469; 2 runs in 136 here: docs/distributed.md#killing-and-restarting-a-process). Taking an
// id whose ports have no segment at all gives the new process new names, which every survivor
// opens afresh.
#pragma once

#include <cstdint>
#include <string>

namespace arbc::dds {

// Fast-DDS's port arithmetic (its PortParameters), restated so that this file needs no
// Fast-DDS header and can be tested alone.
struct DdsPortPlan {
  uint32_t base = 7400;
  uint32_t domain_gain = 250;
  uint32_t participant_gain = 2;
  uint32_t discovery_unicast_offset = 10;  // Fast-DDS's offsetd1
  uint32_t user_unicast_offset = 11;       // Fast-DDS's offsetd3
};

// The lowest participant id below `limit` whose two unicast ports in `domain` have no
// shared-memory segment in `shm_dir`; -1 (let Fast-DDS choose) when every one has.
int participant_id_clear_of_segments(const DdsPortPlan& plan, int domain,
                                     const std::string& shm_dir = "/dev/shm", int limit = 100);

}  // namespace arbc::dds
