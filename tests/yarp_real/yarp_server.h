// A private yarpserver for one test or benchmark process (docs/yarp.md#what-yarp-does): its
// own block of loopback ports, so parallel tests and benchmarks never see each other.
#pragma once

#include <sys/types.h>

#include <string>

namespace arbc::yarp_test {

// A name server port whose block of 100 is this process's alone, or -1. yarpserver gives the
// ports it registers the numbers just above its own, so the block must be free; a lock file
// per block (held until the process exits) keeps parallel processes apart.
int reserve_port_block();

// Starts `yarpserver` (the binary's path) on 127.0.0.1:port, its output in `log`; -1 on failure.
pid_t start_yarpserver(const std::string& yarpserver, int port, const std::string& log);

// SIGTERM, then SIGKILL after 5 s; reaps the process and sets `pid` to -1.
void stop_process(pid_t& pid);

}  // namespace arbc::yarp_test
