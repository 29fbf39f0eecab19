// What the replay test needs from a trace of `arbc run --trace` (docs/runtime.md#trace-format):
// the run's inputs (`publish` lines) and, per destination port, the decisions the runtime made
// (deliveries, and drops after selection), each marked when its outcome depends on timing that
// a replay in wall-clock time cannot reproduce exactly (docs/yarp.md#the-proof-on-real-yarp).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace arbc::yarp_test {

struct Publish {
  double t = 0;
  std::string port;  // "Module.port"
  nlohmann::json value;
};

struct Decision {
  double t = 0;
  std::string connection, port;  // port: the connection's destination
  bool delivered = false;        // else dropped as not-selected or throttled
  nlohmann::json value;          // delivered only
  bool sensitive = false;        // within the tolerance of an expiry or a throttle's end
};

struct RecordedRun {
  std::vector<Publish> publishes;
  std::vector<Decision> decisions;
  double end = 0;  // the time of the last line
};

// Reads `path`; `destination` maps each connection's name to its destination port, and
// `throttle` gives the connections with a throttle period. Decisions after `window` seconds
// and publishes at or after it are left out. A decision at time t is sensitive when, within
// `tolerance` of t, an event entry of its port expires (is not refreshed or unset first) or
// changes presence (the order of messages around it matters), or its connection's throttle
// period ends.
bool read_recorded_run(const std::string& path,
                       const std::map<std::string, std::string>& destination,
                       const std::map<std::string, double>& throttle, double window,
                       double tolerance, RecordedRun* out, std::string* err);

// The comparison of one port's deliveries: arbc's (with their sensitivity) against what YARP
// delivered, both as Bottle texts, aligned by a longest common subsequence.
struct PortComparison {
  size_t arbc = 0, yarp = 0, matched = 0;
  std::vector<std::string> missing;  // arbc delivered, YARP did not, not sensitive: failures
  size_t missing_sensitive = 0;      // arbc delivered, YARP did not, sensitive: tolerated
  std::vector<std::string> extra;    // YARP delivered, arbc did not
};

PortComparison compare_deliveries(const std::vector<std::string>& arbc,
                                  const std::vector<bool>& sensitive,
                                  const std::vector<std::string>& yarp);

}  // namespace arbc::yarp_test
