// What to do when DDS finds a remote endpoint on one of this process's topics with a QoS that
// cannot match this process's endpoint: nothing then flows between them, and without a word
// the run looks as if no program were there at all. The usual causes on a ROS 2 robot are a
// publisher with the sensor-data profile (best effort) in front of arbc's reliable reader, and
// a subscriber that wants a latched topic (transient local) behind arbc's volatile writer;
// both are settled in the deployment file ("qos": {"ports": ...}), not in the program.
#pragma once

#include <string>

#include "dds/deployment.h"

namespace arbc::dds {

// The policy DDS names as the reason two endpoints do not match.
enum class QosPolicy { Reliability, Durability, Other };

struct QosMismatch {
  std::string topic;   // on the wire
  std::string port;    // "Module.port"
  bool reader = true;  // this process's endpoint reads the topic (else writes it)
  QosPolicy policy = QosPolicy::Other;
  std::string policy_name;  // as DDS names it ("DEADLINE"), for Other
};

// The line to report: the topic and port, what each side has, and what to write where (the
// deployment file's place of the port's setting, when the file gives one).
std::string qos_mismatch_text(const Deployment& d, const QosMismatch& m);

}  // namespace arbc::dds
