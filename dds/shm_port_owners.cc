#include "dds/shm_port_owners.h"

namespace arbc::dds {

std::optional<ShmPortOwners::Predecessor> ShmPortOwners::discovered(
    const std::string& id, const std::string& name, const std::vector<uint32_t>& ports) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<Predecessor> found;
  for (uint32_t port : ports) {
    auto it = owners_.find(port);
    if (it != owners_.end() && it->second.id != id && !found) found = {it->second.name, port};
    owners_[port] = {id, name};
  }
  return found;
}

void ShmPortOwners::left(const std::string& id, bool cleanly) {
  if (!cleanly) return;  // a vanished participant's segments may still be mapped here
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = owners_.begin(); it != owners_.end();) {
    it = it->second.id == id ? owners_.erase(it) : std::next(it);
  }
}

}  // namespace arbc::dds
