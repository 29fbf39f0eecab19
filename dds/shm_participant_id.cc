// The participant id whose shared-memory port names no earlier process used
// (dds/shm_participant_id.h says why).
#include "dds/shm_participant_id.h"

#include <filesystem>

namespace arbc::dds {

namespace {

bool segment_exists(const std::string& shm_dir, uint64_t port) {
  std::error_code ec;
  return std::filesystem::exists(shm_dir + "/fastrtps_port" + std::to_string(port), ec);
}

}  // namespace

int participant_id_clear_of_segments(const DdsPortPlan& plan, int domain,
                                     const std::string& shm_dir, int limit) {
  uint64_t domain_base = uint64_t{plan.base} + uint64_t{plan.domain_gain} * uint64_t(domain);
  for (int id = 0; id < limit; ++id) {
    uint64_t step = uint64_t{plan.participant_gain} * uint64_t(id);
    uint64_t discovery = domain_base + plan.discovery_unicast_offset + step;
    uint64_t user = domain_base + plan.user_unicast_offset + step;
    if (user > 65535) break;  // past the last UDP port: Fast-DDS would refuse the id anyway
    if (!segment_exists(shm_dir, discovery) && !segment_exists(shm_dir, user)) return id;
  }
  return -1;
}

}  // namespace arbc::dds
