// The participant and the QoS of every interop program (no arbc code in any), apart from the
// types each registers: a program built from one IDL file includes this without another's
// generated types, which define structs of the same names (Twist.idl, Stamped.idl).
#pragma once

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <string>
#include <thread>

namespace interop {

namespace fdds = eprosima::fastdds::dds;

// The participant of domain `domain`, no type registered; exits on failure.
inline fdds::DomainParticipant* plain_participant(int domain, const char* name) {
  fdds::DomainParticipantFactory* factory = fdds::DomainParticipantFactory::get_instance();
  // The default QoS is Fast-DDS's own until the profiles of FASTRTPS_DEFAULT_PROFILES_FILE are
  // loaded: without this the program ran on the builtin transports (shared memory and UDP on
  // every interface), whatever the profile said (docs/distributed.md#confining-dds-to-one-machine).
  factory->load_profiles();
  fdds::DomainParticipantQos qos = factory->get_default_participant_qos();
  qos.name(name);
  fdds::DomainParticipant* p = factory->create_participant(domain, qos);
  if (!p) {
    std::fprintf(stderr, "%s: cannot create a participant in domain %d\n", name, domain);
    std::exit(3);
  }
  return p;
}

template <class Qos>
void reliable(Qos& qos) {
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 100;
}

// The reliable QoS above, changed by the words `first`.. of the command line: `best_effort`
// (ROS 2's sensor-data profile) and `transient_local` (a latched topic), so that a test can
// give a program the QoS a ROS 2 node may have. Exits on another word.
template <class Qos>
void qos_from_args(Qos& qos, int argc, char** argv, int first) {
  reliable(qos);
  for (int i = first; i < argc; ++i) {
    std::string word = argv[i];
    if (word == "best_effort") {
      qos.reliability().kind = fdds::BEST_EFFORT_RELIABILITY_QOS;
    } else if (word == "transient_local") {
      qos.durability().kind = fdds::TRANSIENT_LOCAL_DURABILITY_QOS;
    } else {
      std::fprintf(stderr, "unknown QoS word '%s' (best_effort, transient_local)\n", argv[i]);
      std::exit(2);
    }
  }
}

// Waits (at most 30 s) until some reader listens on w's topic.
inline bool matched(fdds::DataWriter* w) {
  for (int i = 0; i < 1500; ++i) {
    fdds::PublicationMatchedStatus status;
    w->get_publication_matched_status(status);
    if (status.current_count > 0) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Calls `take` (true when it took a sample) until nothing has come for `linger` seconds after
// the last sample, or for `timeout` seconds when none came at all: how the plain subscribers
// know the run is over.
template <class Take>
void take_until_quiet(Take take, double linger, double timeout) {
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  bool any = false;
  for (;;) {
    if (take()) {
      any = true;
      last = Clock::now();
      continue;
    }
    double quiet = std::chrono::duration<double>(Clock::now() - last).count();
    if (quiet > (any ? linger : timeout)) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace interop
