// What a transport between processes (DDS) knows about its topics at the end of a run, as
// data: `arbc run --report` draws a table from it (report/run_report.h), and the DDS
// transport writes its end-of-run lines from it (Transport::summary), so the two never differ.
// The in-process transport has none.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace arbc {

// One topic this process reads or writes.
struct TransportTopicStatus {
  std::string topic;  // the topic's name on the wire, e.g. "rt/cmd_vel"
  std::string port;   // the app's port it carries, e.g. "Base.cmd_vel"
  std::string type;   // the wire type's name
  bool read = true;   // read here (a mediated source, or a hosted module's input); else written
  bool heard_peer = false;   // a remote writer (read) or reader (written) matched at some time
  bool expects_peer = true;  // the app connects the port; an output nothing reads may be alone
  int peers_now = 0;         // remote endpoints matched at the end
  // Read: samples taken, samples lost (DDS reported them lost in transit, or this process's
  // queue was full), samples that did not decode. Written: samples written, of them written
  // while no subscriber had matched (they reached nobody), writes that failed.
  uint64_t received = 0, lost = 0, undecodable = 0;
  uint64_t written = 0, to_nobody = 0, failed = 0;
};

struct TransportStatus {
  int domain = 0;
  std::vector<TransportTopicStatus> topics;  // those read first, then those written
  std::vector<std::string> notes;            // what discovery found amiss (type mismatches, ...)
};

}  // namespace arbc
