// Which remote participant holds each shared-memory port this process has seen, so that a
// program started in place of a killed one on the same ports is noticed.
//
// arbc's own processes take ports no segment uses (dds/shm_participant_id.h), but a program
// without arbc in it gets Fast-DDS's own id again, hence the killed one's ports. This process
// may then go on writing into the killed one's segment: the new program hears it seconds late,
// or never (docs/distributed.md#killing-and-restarting-a-process). Fast-DDS 2.9 offers no way
// to make it reopen the port; what arbc can do is say so when it happens.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace arbc::dds {

class ShmPortOwners {
 public:
  // A participant `id` named `name` was discovered with these shared-memory ports. Returns
  // the name of another participant that held one of them and did not leave cleanly (still
  // known, or dropped when its lease ran out), with the port; nothing otherwise.
  struct Predecessor {
    std::string name;
    uint32_t port = 0;
  };
  std::optional<Predecessor> discovered(const std::string& id, const std::string& name,
                                        const std::vector<uint32_t>& ports);
  // The participant deleted itself (its ports are free again), or its lease ran out (it
  // vanished: a killed process, whose segments a survivor may still have mapped).
  void left(const std::string& id, bool cleanly);

 private:
  struct Owner {
    std::string id, name;
  };
  std::mutex mutex_;
  std::map<uint32_t, Owner> owners_;
};

}  // namespace arbc::dds
